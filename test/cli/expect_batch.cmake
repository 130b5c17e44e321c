# SPDX-License-Identifier: GPL-3.0-or-later
# --sources FILE --out-dir DIR: for every source k, DIR/ridge_k.polylines.txt
# equals the --ridge file of a single run from that source, and
# DIR/ridge_k.json names the source. Run on torus_1k (vertices and a point)
# and on a mesh in two parts (sources on both: one batch per part).
#   cmake -DCLI=prog -DD=data -DB=cli_data -DOUT=dir -P expect_batch.cmake
set(dir ${OUT}/batch)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${OUT})

function(check mesh tag)
  # ARGN: the sources, each "V" or "FACE;X;Y;Z"
  set(list_file ${OUT}/batch_${tag}_sources.txt)
  file(WRITE ${list_file} "# sources of the batch test\n")
  foreach(s ${ARGN})
    string(REPLACE "," " " line "${s}")
    file(APPEND ${list_file} "${line}\n")
  endforeach()
  execute_process(COMMAND ${CLI} ${mesh} --sources ${list_file} --out-dir ${dir}/${tag}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${tag}: --sources exit ${rc}\n${out}\n${err}")
  endif()
  set(k 0)
  foreach(s ${ARGN})
    string(REPLACE "," ";" args "${s}")
    list(LENGTH args n)
    if(n EQUAL 1)
      set(single --source-vertex ${args})
    else()
      set(single --source-point ${args})
    endif()
    execute_process(COMMAND ${CLI} ${mesh} ${single} --ridge ${OUT}/batch_${tag}_single_${k}.txt
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${tag}: single run ${single}: exit ${rc}\n${err}")
    endif()
    file(READ ${OUT}/batch_${tag}_single_${k}.txt expected)
    file(READ ${dir}/${tag}/ridge_${k}.polylines.txt got)
    if(NOT got STREQUAL expected)
      message(FATAL_ERROR "${tag}: source ${k} (${s}): the batch's ridge differs from the single run's")
    endif()
    file(READ ${dir}/${tag}/ridge_${k}.json json)
    string(REPLACE "," " " text "${s}")
    if(NOT json MATCHES "\"source\": \"${text}\"")
      message(FATAL_ERROR "${tag}: ridge_${k}.json does not name the source '${text}'")
    endif()
    math(EXPR k "${k} + 1")
  endforeach()
  message(STATUS "${tag}: ${k} sources, each as a single run")
endfunction()

check(${D}/torus_1k.off torus 0 17 "0,1.3573468999999998,0.7423328699999999,1.4680988666666668" 400)
check(${B}/cube_and_octahedron.off two_parts 10 0 12 3)

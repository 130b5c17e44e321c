# SPDX-License-Identifier: GPL-3.0-or-later
# Every output of a single run is written beside its target and renamed onto
# it: after a run with all of them, the directory holds exactly the outputs;
# after a write that fails (the target is a directory: the rename fails), the
# temporary file is gone too.
#   cmake -DCLI=prog -DD=data -DB=cli_data -DOUT=dir -P expect_whole_outputs.cmake
include(${CMAKE_CURRENT_LIST_DIR}/no_temporaries.cmake)
set(dir ${OUT}/whole_outputs)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
set(outputs ridge.polylines.txt ridge_locations.txt rough_cut.polylines.txt refined.ply isolines.polylines.txt
            distances.txt stats.json picture.png)
execute_process(COMMAND ${CLI} ${D}/torus_1k.off --source-vertex 0 --ridge ${dir}/ridge.polylines.txt
                        --ridge-locations ${dir}/ridge_locations.txt --rough-cut ${dir}/rough_cut.polylines.txt
                        --refined ${dir}/refined.ply --isolines 5 ${dir}/isolines.polylines.txt
                        --query ${B}/queries_torus_1k_points.txt --query-out ${dir}/distances.txt
                        --stats ${dir}/stats.json --png ${dir}/picture.png
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "exit ${rc}\n${out}\n${err}")
endif()
# (CMake's glob matches names that start with a dot too)
file(GLOB found RELATIVE ${dir} ${dir}/*)
list(SORT found)
list(SORT outputs)
if(NOT found STREQUAL outputs)
  message(FATAL_ERROR "the directory holds '${found}', expected '${outputs}'")
endif()
foreach(f ${outputs})
  file(SIZE ${dir}/${f} size)
  if(size EQUAL 0)
    message(FATAL_ERROR "${f} is empty")
  endif()
endforeach()
# a target that is a directory: the rename fails, the temporary is removed
file(MAKE_DIRECTORY ${dir}/taken)
execute_process(COMMAND ${CLI} ${D}/torus_1k.off --source-vertex 0 --stats ${dir}/taken
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "error: cannot write '${dir}/taken'")
  message(FATAL_ERROR "a directory as the target: exit ${rc}\n${err}")
endif()
expect_no_temporaries(${dir} "the outputs")
message(STATUS "${outputs}: whole, no temporary file")

# SPDX-License-Identifier: GPL-3.0-or-later
# The mesh scaled by 10^EXPONENT (written by appending "e<EXPONENT>" to every
# coordinate of MESH, whose coordinates have no exponent: exact decimal
# scaling, no arithmetic here) gives what the mesh gives: every output
# written, the picture showing the surface, the ridge and the source (decoded
# by png_check), the query distances the same in their first 9 digits, the
# stats' ridge one component without cycles (genus 0) or with 2g cycles.
#   cmake -DCLI=prog -DCHECK=png_check -DMESH=torus_1k.off -DDATA=test/cli/data -DEXPONENT=-300 -DGENUS=1 -DOUT=dir [-DEXTRA=...] -P expect_any_scale.cmake
file(MAKE_DIRECTORY ${OUT})
get_filename_component(name ${MESH} NAME_WE)
set(scaled ${OUT}/${name}_e${EXPONENT}.off)
file(STRINGS ${MESH} lines)
list(GET lines 1 counts)
string(REGEX MATCH "^[0-9]+" nv "${counts}")
set(text "")
set(i 0)
foreach(line IN LISTS lines)
  math(EXPR vertex "${i} - 2")
  if(i GREATER 1 AND vertex LESS nv)
    if(line MATCHES "[eE]")
      message(FATAL_ERROR "${MESH}: a coordinate with an exponent: '${line}'")
    endif()
    string(REGEX REPLACE "([-0-9.]+)" "\\1e${EXPONENT}" line "${line}")
  endif()
  string(APPEND text "${line}\n")
  math(EXPR i "${i} + 1")
endforeach()
file(WRITE ${scaled} "${text}")

foreach(run plain scaled)
  if(run STREQUAL "plain")
    set(mesh ${MESH})
  else()
    set(mesh ${scaled})
  endif()
  set(prefix ${OUT}/${name}_${run}${EXPONENT})
  execute_process(COMMAND ${CLI} ${mesh} --source-vertex 0 ${EXTRA}
                          --query ${DATA}/queries_torus_1k_barycentric.txt --query-barycentric
                          --query-out ${prefix}_queries.txt --refined ${prefix}.ply
                          --isolines 8 ${prefix}_isolines.txt --ridge ${prefix}_ridge.txt
                          --png ${prefix}.png --stats ${prefix}_stats.json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${run}: exit ${rc}\n${out}\n${err}")
  endif()
  foreach(f ${prefix}_queries.txt ${prefix}.ply ${prefix}_isolines.txt ${prefix}_ridge.txt ${prefix}.png)
    file(SIZE ${f} size)
    if(size EQUAL 0)
      message(FATAL_ERROR "${run}: ${f} is empty")
    endif()
  endforeach()
  execute_process(COMMAND ${CHECK} ${prefix}.png 1200 600 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${run}: the picture: ${out}${err}")
  endif()
  file(READ ${prefix}_stats.json stats)
  string(JSON components GET "${stats}" statistics ridge components)
  string(JSON cycles GET "${stats}" statistics ridge cycles)
  math(EXPR expected "2 * ${GENUS}")
  if(NOT components EQUAL 1 OR NOT cycles EQUAL expected)
    message(FATAL_ERROR "${run}: the ridge has ${components} components and ${cycles} cycles, expected 1 and ${expected}")
  endif()
  # the significant digits of each distance: "0.0246087..." and
  # "2.46087...e-302" both give "246087..."
  file(STRINGS ${prefix}_queries.txt distances)
  set(digits_${run} "")
  foreach(d IN LISTS distances)
    string(REGEX REPLACE "[eE].*$" "" m "${d}")
    string(REPLACE "." "" m "${m}")
    string(REGEX REPLACE "^0+" "" m "${m}")
    string(SUBSTRING "${m}0000000000" 0 9 m)
    list(APPEND digits_${run} "${m}")
  endforeach()
endforeach()
list(REMOVE_AT digits_plain 1) # the source: 0 in both
list(REMOVE_AT digits_scaled 1)
if(NOT digits_plain STREQUAL digits_scaled)
  message(FATAL_ERROR "the query distances differ: ${digits_plain} against ${digits_scaled} (first 9 digits)")
endif()

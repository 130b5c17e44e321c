# SPDX-License-Identifier: GPL-3.0-or-later
# Runs geodesic_ridge with every output of the region-wise field and checks
# them: queries in both forms give the same distances (the corners' distances
# are the vertex distances, so the order of the barycentric coordinates is
# checked too: vertex 0 is the source and the second corner of face 0), the
# refined mesh is a PLY with the two properties, iso-lines and ridge locations
# are written, and the stats say which ridge was written.
#   cmake -DCLI=prog -DMESH=torus_1k.off -DDATA=test/cli/data -DOUT=dir [-DEXTRA=...] -P expect_field_outputs.cmake
file(MAKE_DIRECTORY ${OUT})
get_filename_component(name ${MESH} NAME_WE)
set(prefix ${OUT}/${name}_field)
execute_process(COMMAND ${CLI} ${MESH} --source-vertex 0 ${EXTRA}
                        --query ${DATA}/queries_torus_1k_barycentric.txt --query-barycentric
                        --query-out ${prefix}_barycentric.txt --refined ${prefix}.ply
                        --isolines 8 ${prefix}_isolines.txt --ridge-locations ${prefix}_ridge.txt
                        --stats ${prefix}_stats.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "exit ${rc}\n${out}\n${err}")
endif()
execute_process(COMMAND ${CLI} ${MESH} --source-vertex 0 ${EXTRA}
                        --query ${DATA}/queries_torus_1k_points.txt --query-out ${prefix}_points.txt
                        --isolines 8 ${prefix}_isolines_vertices.txt --isolines-from-vertices
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "exit ${rc}\n${out}\n${err}")
endif()
file(STRINGS ${prefix}_barycentric.txt by_barycentric)
file(STRINGS ${prefix}_points.txt by_point)
list(LENGTH by_barycentric n1)
list(LENGTH by_point n2)
if(NOT n1 EQUAL 4 OR NOT n2 EQUAL 4)
  message(FATAL_ERROR "expected 4 distances each, got ${n1} and ${n2}")
endif()
# vertex 0 (the source) is the second corner of face 0 in the file
list(GET by_barycentric 1 at_source)
if(NOT at_source MATCHES "^(0|[0-9.]+e-(1[3-9]|[2-9][0-9]|[1-9][0-9][0-9]))$")
  message(FATAL_ERROR "the distance at the source (corner 2 of face 0) is '${at_source}', expected 0 (or below 1e-12 with the cone field)")
endif()
foreach(i 0 1 2 3)
  list(GET by_barycentric ${i} a)
  list(GET by_point ${i} b)
  if(NOT a MATCHES "^[0-9]+(\\.[0-9]+)?(e-?[0-9]+)?$")
    message(FATAL_ERROR "query ${i}: '${a}' is not a distance")
  endif()
  string(SUBSTRING "${a}" 0 10 a10)
  string(SUBSTRING "${b}" 0 10 b10)
  if(NOT a10 STREQUAL b10)
    message(FATAL_ERROR "query ${i}: barycentric gives ${a}, the point gives ${b}")
  endif()
endforeach()
file(READ ${prefix}.ply header LIMIT 600)
foreach(property "property double distance" "property int source_face" "format ascii")
  string(FIND "${header}" "${property}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the refined mesh's header lacks '${property}':\n${header}")
  endif()
endforeach()
foreach(f ${prefix}_isolines.txt ${prefix}_isolines_vertices.txt ${prefix}_ridge.txt)
  file(STRINGS ${f} lines)
  list(LENGTH lines n)
  if(n LESS 8)
    message(FATAL_ERROR "${f}: only ${n} lines")
  endif()
endforeach()
# with the exact solver (the cone field too) the ridge written is the cone
# ridge (its counts in the stats); the other solvers have none
file(READ ${prefix}_stats.json stats)
string(REGEX MATCH "\"cone_polylines\": ([0-9]+)" found "${stats}")
if(NOT found)
  message(FATAL_ERROR "the stats do not count the cone ridge's polylines")
endif()
set(cone_polylines ${CMAKE_MATCH_1}) # (the MATCHES below overwrite CMAKE_MATCH_1)
if("${EXTRA}" MATCHES "cone|exact|vtp" AND cone_polylines EQUAL 0)
  message(FATAL_ERROR "the stats of a run with cones (exact, vtp) have no cone polylines")
elseif(NOT "${EXTRA}" MATCHES "cone|exact|vtp" AND NOT cone_polylines EQUAL 0)
  message(FATAL_ERROR "the stats of a run without cones have cone polylines")
endif()
message(STATUS "queries: ${by_barycentric}")

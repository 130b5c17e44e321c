# SPDX-License-Identifier: GPL-3.0-or-later
# A mesh in two parts: a cube of quads (file vertices 0-7, faces 0-5) and the
# octahedron of octahedron.off (vertices 8-13, faces 6-13). From a source on
# the octahedron, the ridge, the iso-lines and the distances must be those of
# octahedron.off alone (the same ridge and iso-line files; distances to 15
# digits: the copy of the part numbers its vertices in another order), and the
# cube is unreachable: a note on stderr, 'inf' for its queries, distance -1 at
# its 8 vertices in the refined PLY, grey in the picture, counted in the
# stats. From a source on the cube, the octahedron is the unreachable part.
#   cmake -DCLI=prog -DCHECK=png_check -DDATA=dir -DOUT=dir -P expect_components.cmake
file(MAKE_DIRECTORY ${OUT})
set(two_parts ${DATA}/cube_and_octahedron.off)
set(p ${OUT}/components)

function(run mesh source tag)
  execute_process(COMMAND ${CLI} ${mesh} --source-vertex ${source} --ridge ${p}_${tag}_ridge.txt
                          --isolines 5 ${p}_${tag}_iso.txt ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${mesh} --source-vertex ${source}: exit ${rc}\n${out}\n${err}")
  endif()
  set(stderr_${tag} "${err}" PARENT_SCOPE)
endfunction()

# expect_lines(file a;b;...): line i of the file starts with item i
function(expect_lines file)
  file(STRINGS ${file} lines)
  list(LENGTH lines n)
  list(LENGTH ARGN m)
  if(NOT n EQUAL m)
    message(FATAL_ERROR "${file}: ${n} lines, expected ${m}")
  endif()
  set(i 0)
  foreach(line start IN ZIP_LISTS lines ARGN)
    string(FIND "${line}" "${start}" at)
    if(NOT at EQUAL 0)
      message(FATAL_ERROR "${file} line ${i}: '${line}', expected '${start}...'")
    endif()
    math(EXPR i "${i} + 1")
  endforeach()
endfunction()

run(${DATA}/octahedron.off 0 alone --query ${DATA}/queries_octahedron_points.txt --query-out ${p}_alone_q.txt)
run(${two_parts} 8 two --query ${DATA}/queries_cube_and_octahedron_points.txt --query-out ${p}_two_q.txt
    --refined ${p}_two.ply --ply-ascii --png ${p}_two.png --stats ${p}_two.json)
if(NOT stderr_two MATCHES "note: the mesh has 2 connected components; the ridge is that of the source's \\(8 of 20 faces\\); the other 1 \\(12 faces\\) is unreachable from it")
  message(FATAL_ERROR "no note of the unreachable part on stderr:\n${stderr_two}")
endif()
foreach(suffix _ridge.txt _iso.txt)
  file(READ ${p}_alone${suffix} alone)
  file(READ ${p}_two${suffix} two)
  if(NOT alone STREQUAL two)
    message(FATAL_ERROR "${suffix}: the two-part mesh's differs from octahedron.off's:\n${two}\n---\n${alone}")
  endif()
endforeach()
file(STRINGS ${p}_alone_q.txt alone)
list(GET alone 0 a0)
list(GET alone 1 a1)
string(SUBSTRING "${a0}" 0 15 a0)
string(SUBSTRING "${a1}" 0 15 a1)
expect_lines(${p}_two_q.txt "${a0}" inf "${a1}" inf)

# the refined mesh: the cube's 8 vertices at distance -1, none other
file(STRINGS ${p}_two.ply vertex_lines REGEX "^[-0-9.e]+ [-0-9.e]+ [-0-9.e]+ [-0-9.e]+ ?$")
set(unreachable 0)
set(reachable 0)
foreach(line IN LISTS vertex_lines)
  if(line MATCHES " -1 ?$")
    math(EXPR unreachable "${unreachable} + 1")
  else()
    math(EXPR reachable "${reachable} + 1")
  endif()
endforeach()
if(NOT unreachable EQUAL 8 OR NOT reachable EQUAL 6)
  message(FATAL_ERROR "refined PLY: ${unreachable} vertices at -1 (expected 8), ${reachable} others (expected 6)")
endif()

file(READ ${p}_two.json stats)
foreach(re "\"connected_components\": 2" "\"other_components_vertices\": 8" "\"other_components_faces\": 12"
           "\"source\": {[^}]*\"vertex\": 8")
  if(NOT stats MATCHES "${re}")
    message(FATAL_ERROR "the stats lack '${re}':\n${stats}")
  endif()
endforeach()

execute_process(COMMAND ${CHECK} ${p}_two.png 1200 600 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCH "([0-9]+) grey" grey "${out}")
if(NOT rc EQUAL 0 OR CMAKE_MATCH_1 LESS 1000)
  message(FATAL_ERROR "the picture does not show the cube grey:\n${out}${err}")
endif()
message(STATUS "${out}")

# a source on the cube: the octahedron is unreachable
run(${two_parts} 0 cube --query ${DATA}/queries_cube_and_octahedron_points.txt --query-out ${p}_cube_q.txt)
if(NOT stderr_cube MATCHES "the ridge is that of the source's \\(12 of 20 faces\\); the other 1 \\(8 faces\\)")
  message(FATAL_ERROR "no note of the unreachable part on stderr:\n${stderr_cube}")
endif()
expect_lines(${p}_cube_q.txt inf 0.75 inf 1.707106781186) # the linear field: 0.25 + 0.5; 1 + sqrt(2)/2

# SPDX-License-Identifier: GPL-3.0-or-later
# Runs geodesic_ridge with --repair on a dirty mesh, and on a clean mesh of the
# same surface whose file indices are the ones the dirty file's must map to,
# and checks that every output that speaks in file indices is the same: the
# ridge locations (FACE and one coordinate per vertex of the file face) and
# the distances at queries given as FACE X Y Z or as barycentric coordinates;
# and the ridge itself. With -DREORDERED_FACES=ON (the dirty file lists some
# face's vertices in another order, e.g. reversed) the ridge locations, whose
# coordinates follow that order, are not compared.
# Also checks that the stats give the source as the dirty file's vertex and say
# that the mesh was repaired, and that stderr says what the repair did (every
# regular expression of NOTES matches it).
#   cmake -DCLI=prog -DDIRTY=mesh -DDIRTY_SOURCE=v -DCLEAN=mesh -DCLEAN_SOURCE=v [-DCLEAN_EXTRA=args]
#         [-DQUERIES=file] [-DBARYCENTRIC=file] [-DNOTES="re;..."] [-DREORDERED_FACES=ON] -DOUT=dir
#         -P expect_repair.cmake
file(MAKE_DIRECTORY ${OUT})
get_filename_component(name ${DIRTY} NAME_WE)
set(prefix ${OUT}/${name})

# run(tag mesh source args...): the outputs are ${prefix}_${tag}*.txt
function(run tag mesh source)
  set(queries)
  if(QUERIES)
    list(APPEND queries --query ${QUERIES} --query-out ${prefix}_${tag}_points.txt)
  endif()
  execute_process(COMMAND ${CLI} ${mesh} --source-vertex ${source} ${ARGN} --ridge-locations ${prefix}_${tag}.txt
                          --ridge ${prefix}_${tag}_ridge.txt --stats ${prefix}_${tag}.json ${queries}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${mesh}: exit ${rc}\n${out}\n${err}")
  endif()
  if(BARYCENTRIC)
    execute_process(COMMAND ${CLI} ${mesh} --source-vertex ${source} ${ARGN} --query ${BARYCENTRIC}
                            --query-barycentric --query-out ${prefix}_${tag}_barycentric.txt
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out2 ERROR_VARIABLE err2)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${mesh} (barycentric queries): exit ${rc}\n${out2}\n${err2}")
    endif()
  endif()
  set(stderr_${tag} "${err}" PARENT_SCOPE)
endfunction()

run(dirty ${DIRTY} ${DIRTY_SOURCE} --repair)
run(clean ${CLEAN} ${CLEAN_SOURCE} ${CLEAN_EXTRA})
foreach(re IN LISTS NOTES)
  if(NOT stderr_dirty MATCHES "${re}")
    message(FATAL_ERROR "stderr does not match '${re}':\n${stderr_dirty}")
  endif()
endforeach()

set(outputs _ridge.txt)
if(NOT REORDERED_FACES)
  list(APPEND outputs .txt)
endif()
if(QUERIES)
  list(APPEND outputs _points.txt)
endif()
if(BARYCENTRIC)
  list(APPEND outputs _barycentric.txt)
endif()
foreach(suffix IN LISTS outputs)
  file(READ ${prefix}_dirty${suffix} dirty)
  file(READ ${prefix}_clean${suffix} clean)
  if(NOT dirty STREQUAL clean)
    message(FATAL_ERROR "${name}_dirty${suffix} and ${name}_clean${suffix} differ:\n${dirty}\n---\n${clean}")
  endif()
  string(REGEX MATCHALL "\n[0-9]" lines "${dirty}")
  list(LENGTH lines n)
  message(STATUS "${name}${suffix}: the same ${n} lines")
endforeach()

file(READ ${prefix}_dirty.json stats)
string(REGEX MATCH "\"source\": {[^}]*\"vertex\": ([0-9]+)" source "${stats}")
set(source "${CMAKE_MATCH_1}")
string(REGEX MATCH "\"repaired\": (true|false)" repaired "${stats}")
set(repaired "${CMAKE_MATCH_1}")
if(NOT source STREQUAL DIRTY_SOURCE OR NOT repaired STREQUAL "true")
  message(FATAL_ERROR "the stats give source vertex '${source}' (expected ${DIRTY_SOURCE}), repaired '${repaired}'")
endif()

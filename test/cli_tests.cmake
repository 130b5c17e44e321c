# SPDX-License-Identifier: GPL-3.0-or-later
# Command-line tests of geodesic_ridge: bad input must give a one-line error
# and a non-zero exit; good input must write a valid rough cut.
if(NOT TARGET geodesic_ridge)
  return()
endif()
set(CLI $<TARGET_FILE:geodesic_ridge>)
set(D ${GEODESIC_RIDGE_SOURCE_DIR}/data)
set(B ${CMAKE_CURRENT_SOURCE_DIR}/cli/data)

function(cli_failure name expect)
  add_test(NAME cli.error.${name}
           COMMAND ${CMAKE_COMMAND} "-DEXPECT=${expect}" "-DCOMMAND=${ARGN}"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_failure.cmake)
endfunction()

cli_failure(no_arguments          "missing the MESH argument" ${CLI})
cli_failure(missing_source        "missing the source" ${CLI} ${D}/torus_1k.off)
cli_failure(unknown_option        "unknown option '--frobnicate'" ${CLI} ${D}/torus_1k.off --source-vertex 0 --frobnicate)
cli_failure(option_without_value  "option --tolerance needs a value" ${CLI} ${D}/torus_1k.off --source-vertex 0 --tolerance)
cli_failure(two_sources           "one source only" ${CLI} ${D}/torus_1k.off --source-vertex 0 --source-vertex 1)
cli_failure(missing_file          "no_such_mesh.off" ${CLI} ${B}/no_such_mesh.off --source-vertex 0)
cli_failure(garbage_file          "garbage.off" ${CLI} ${B}/garbage.off --source-vertex 0)
cli_failure(truncated_file        "truncated" ${CLI} ${B}/truncated.off --source-vertex 0)
# a header that announces more than the file can hold is refused before anything is allocated
cli_failure(huge_counts_off       "file is truncated: the header announces 2000000000 vertices and 2000000000 faces, but it ends after 4 vertices"
            ${CLI} ${B}/huge_counts.off --source-vertex 0)
cli_failure(huge_counts_ply       "the header announces 3 'vertex', 2000000000 'face', which take at least .* bytes, but the file has 227"
            ${CLI} ${B}/huge_counts.ply --source-vertex 0)
cli_failure(nan_coordinate        "(NaN|nan|finite|malformed|cannot read)" ${CLI} ${B}/nan_coordinate.off --source-vertex 0)
# quads.off: two quads (triangulated, with a note) and an isolated vertex
function(cli_failure_after_notes name expect notes)
  add_test(NAME cli.error.${name}
           COMMAND ${CMAKE_COMMAND} "-DEXPECT=${expect}" "-DNOTES=${notes}" "-DCOMMAND=${ARGN}"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_failure.cmake)
endfunction()
cli_failure_after_notes(isolated_vertex_after_polygons "vertex 4 is isolated .*\\(use --repair\\)$"
                        "note: 2 polygons triangulated into 4 triangles; 0 not planar" ${CLI} ${B}/quads.off --source-vertex 0)
cli_failure(source_out_of_range   "source vertex 500 is out of range" ${CLI} ${D}/torus_1k.off --source-vertex 500)
cli_failure(source_not_a_number   "source vertex 'abc' is not a non-negative integer" ${CLI} ${D}/torus_1k.off --source-vertex abc)
cli_failure(source_negative       "source vertex '-1' is not a non-negative integer" ${CLI} ${D}/torus_1k.off --source-vertex -1)
cli_failure(source_face_range     "source face 1000 is out of range" ${CLI} ${D}/torus_1k.off --source-point 1000 0 0 0)
cli_failure(source_point_off_face "is not on face 0" ${CLI} ${D}/torus_1k.off --source-point 0 100 100 100)
# far from the face (the coordinates huge, NaN, or summing to 0): off the face, not "removed"
cli_failure(source_point_far      "is not on face 0" ${CLI} ${D}/torus_1k.off --source-point 0 0.5 0.5 1e300)
cli_failure(source_point_nan      "source x 'nan' is not a finite number" ${CLI} ${D}/torus_1k.off --source-point 0 nan 0 0)
cli_failure(tolerance_too_large   "tolerance 0.5.* out of range" ${CLI} ${D}/torus_1k.off --source-vertex 0 --tolerance 0.5)
cli_failure(tolerance_negative    "out of range" ${CLI} ${D}/torus_1k.off --source-vertex 0 --tolerance -0.01)
cli_failure(tolerance_not_number  "tolerance 'x1' is not a finite number" ${CLI} ${D}/torus_1k.off --source-vertex 0 --tolerance x1)
cli_failure(tolerance_nan         "tolerance 'nan' is not a finite number" ${CLI} ${D}/torus_1k.off --source-vertex 0 --tolerance nan)
cli_failure(unwritable_output     "cannot open" ${CLI} ${D}/torus_1k.off --source-vertex 0 --rough-cut /nonexistent-dir/x.txt)
cli_failure(unknown_solver        "unknown solver 'mmp'" ${CLI} ${D}/torus_1k.off --source-vertex 0 --solver mmp)
cli_failure(sources_without_dir   "--sources and --out-dir go together" ${CLI} ${D}/torus_1k.off --sources ${B}/queries_torus_1k_points.txt)
cli_failure(sources_and_source    "give --sources or one source, not both" ${CLI} ${D}/torus_1k.off --source-vertex 0
            --sources ${B}/queries_torus_1k_points.txt --out-dir ${CMAKE_CURRENT_BINARY_DIR}/cli_out/never)
# a source file that does not parse is refused before any work (a source that
# is out of range or off its face fails alone: cli.batch.errors)
cli_failure(sources_bad_line      "source file '.*queries_malformed.txt' line 2: expected 'V' or 'FACE X Y Z', got 3 fields"
            ${CLI} ${D}/torus_1k.off --sources ${B}/queries_malformed.txt --out-dir ${CMAKE_CURRENT_BINARY_DIR}/cli_out/never)
cli_failure(sources_bad_number    "source file '.*queries_nan.txt' line 1: coordinate 'nan' is not a finite number"
            ${CLI} ${D}/torus_1k.off --sources ${B}/queries_nan.txt --out-dir ${CMAKE_CURRENT_BINARY_DIR}/cli_out/never)
cli_failure(sources_bad_tolerance "tolerance 0.5.* out of range" ${CLI} ${D}/torus_1k.off --tolerance 0.5
            --sources ${B}/queries_torus_1k_points.txt --out-dir ${CMAKE_CURRENT_BINARY_DIR}/cli_out/never)
add_test(NAME cli.batch
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DD=${D} -DB=${B} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/cli_out
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_batch.cmake)
# sources that fail: an error file each, the others go on, summary.json, exit 1
if(NOT CMAKE_VERSION VERSION_LESS 3.19) # string(JSON)
  add_test(NAME cli.batch.errors
           COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DD=${D} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/cli_out
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_batch_errors.cmake)
  # (its own test: the sanitizer run skips the heat method by name)
  add_test(NAME cli.batch.errors_heat
           COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DD=${D} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/cli_out -DHEAT=ON
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_batch_errors.cmake)
endif()
# every output whole or not at all: written beside, then renamed
add_test(NAME cli.outputs_whole
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DD=${D} -DB=${B} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/cli_out
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_whole_outputs.cmake)
find_program(GEODESIC_RIDGE_BASH bash)
if(GEODESIC_RIDGE_BASH AND EXISTS /usr/bin/python3)
  add_test(NAME cli.batch.killed
           COMMAND ${GEODESIC_RIDGE_BASH} ${CMAKE_CURRENT_SOURCE_DIR}/cli/kill_batch.sh ${CLI} ${D}/torus_1k.off
                   ${CMAKE_CURRENT_BINARY_DIR}/cli_out)
endif()
cli_failure(heat_point_source     "the heat solver takes a vertex as the source" ${CLI} ${D}/torus_1k.off
            --source-point 0 1.3573468999999998 0.7423328699999999 1.4680988666666668 --solver heat)
cli_failure(unwritable_png        "cannot open" ${CLI} ${D}/torus_1k.off --source-vertex 0 --png /nonexistent-dir/x.png)

# Good input: every bundled mesh, from a vertex and from a surface point.
set(OUTDIR ${CMAKE_CURRENT_BINARY_DIR}/cli_out)
foreach(mesh_genus bunny_1k:0 armadillo_2k:0 torus_1k:1 knot_3k:1 eight:2 3holes_7k:3)
  string(REPLACE ":" ";" mg ${mesh_genus})
  list(GET mg 0 mesh)
  list(GET mg 1 genus)
  foreach(source "--source-vertex;0" "--source-vertex;17")
    string(REPLACE ";" "_" tag "${source}")
    add_test(NAME cli.rough_cut.${mesh}${tag}
             COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DMESH=${D}/${mesh}.off "-DSOURCE=${source}"
                     -DOUT=${OUTDIR} -DGENUS=${genus} -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_rough_cut.cmake)
  endforeach()
endforeach()
# a surface point: the centroid of face 0 of torus_1k
add_test(NAME cli.rough_cut.torus_1k_source_point
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DMESH=${D}/torus_1k.off
                 "-DSOURCE=--source-point;0;1.3573468999999998;0.7423328699999999;1.4680988666666668" -DOUT=${OUTDIR} -DGENUS=1
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_rough_cut.cmake)
# the approximate solvers on the extended surface: the same checks
foreach(solver vtp fmm heat heat-idt dijkstra)
  foreach(mesh_genus bunny_1k:0 eight:2)
    string(REPLACE ":" ";" mg ${mesh_genus})
    list(GET mg 0 mesh)
    list(GET mg 1 genus)
    add_test(NAME cli.ridge.${solver}.${mesh}
             COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DMESH=${D}/${mesh}.off "-DSOURCE=--source-vertex;5"
                     "-DEXTRA=--solver;${solver}" -DOUT=${OUTDIR}/${solver} -DGENUS=${genus}
                     -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_rough_cut.cmake)
  endforeach()
endforeach()

# The region-wise field: queries, refined mesh, iso-lines, ridge locations,
# with both solvers; and bad query files.
foreach(solver exact vtp fmm)
  add_test(NAME cli.field.${solver}
           COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DMESH=${D}/torus_1k.off -DDATA=${B} -DOUT=${OUTDIR}/${solver}
                   "-DEXTRA=--solver;${solver}" -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_field_outputs.cmake)
endforeach()
add_test(NAME cli.field.cone
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DMESH=${D}/torus_1k.off -DDATA=${B} -DOUT=${OUTDIR}/cone
                 "-DEXTRA=--field;cone" -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_field_outputs.cmake)
# the cone field of window propagation: the exact lower envelope of its windows
add_test(NAME cli.field.cone_vtp
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DMESH=${D}/torus_1k.off -DDATA=${B} -DOUT=${OUTDIR}/cone_vtp
                 "-DEXTRA=--solver;vtp;--field;cone" -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_field_outputs.cmake)
# any scale (issue 41): the torus scaled by 1e-300 and 1e300 gives every
# output, the same distances and a ridge of the right topology
foreach(exponent -300 300)
  foreach(solver exact fmm)
    add_test(NAME cli.scale.${solver}.e${exponent}
             COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DCHECK=$<TARGET_FILE:png_check> -DMESH=${D}/torus_1k.off
                     -DDATA=${B} -DEXPONENT=${exponent}
                     -DGENUS=1 -DOUT=${OUTDIR}/scale_${solver} "-DEXTRA=--solver;${solver}"
                     -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_any_scale.cmake)
  endforeach()
endforeach()
cli_failure(cone_with_fmm         "the cone field needs a solver with cones: exact or vtp" ${CLI} ${D}/torus_1k.off --source-vertex 0 --solver fmm --field cone)
# without the exact solver's corner fallback samples (parameters::corner_fallback(false))
add_test(NAME cli.ridge.no_corner_fallback.bunny_1k
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DMESH=${D}/bunny_1k.off "-DSOURCE=--source-vertex;5"
                 "-DEXTRA=--no-corner-fallback" -DOUT=${OUTDIR}/no_corner_fallback -DGENUS=0
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_rough_cut.cmake)
# the linear field's ridge instead of the cone ridge
add_test(NAME cli.ridge.linear_ridge.bunny_1k
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DMESH=${D}/bunny_1k.off "-DSOURCE=--source-vertex;5"
                 "-DEXTRA=--linear-ridge" -DOUT=${OUTDIR}/linear_ridge -DGENUS=0
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_rough_cut.cmake)
add_test(NAME cli.ridge.linear_ridge_vtp.bunny_1k
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DMESH=${D}/bunny_1k.off "-DSOURCE=--source-vertex;5"
                 "-DEXTRA=--solver;vtp;--linear-ridge" -DOUT=${OUTDIR}/linear_ridge_vtp -DGENUS=0
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_rough_cut.cmake)
cli_failure(linear_ridge_fmm      "--linear-ridge is for the solvers with cones" ${CLI} ${D}/torus_1k.off --source-vertex 0 --solver fmm --linear-ridge)
cli_failure(linear_ridge_cone     "--linear-ridge is not for the cone field" ${CLI} ${D}/torus_1k.off --source-vertex 0 --field cone --linear-ridge)
cli_failure(no_corner_fallback_fmm  "--no-corner-fallback is for the solvers with cones" ${CLI} ${D}/torus_1k.off --source-vertex 0 --solver fmm --no-corner-fallback)
cli_failure(no_corner_fallback_cone "--no-corner-fallback is for the linear field" ${CLI} ${D}/torus_1k.off --source-vertex 0 --field cone --no-corner-fallback)
cli_failure(unknown_field         "unknown field 'planar'" ${CLI} ${D}/torus_1k.off --source-vertex 0 --field planar)
set(Q ${D}/torus_1k.off --source-vertex 0 --query-out ${OUTDIR}/q.txt --query)
cli_failure(query_bad_face        "line 1: face 5000 is out of range" ${CLI} ${Q} ${B}/queries_bad_face.txt)
cli_failure(query_malformed       "line 2: expected 'FACE X Y Z', got 3 fields" ${CLI} ${Q} ${B}/queries_malformed.txt)
cli_failure(query_nan             "line 1: coordinate 'nan' is not a finite number" ${CLI} ${Q} ${B}/queries_nan.txt)
cli_failure(query_off_face        "line 1: point .* is not on face 0" ${CLI} ${Q} ${B}/queries_off_face.txt)
cli_failure(query_bad_sum         "line 1: barycentric coordinates must be >= 0 and sum to 1" ${CLI} ${Q} ${B}/queries_bad_sum.txt --query-barycentric)
cli_failure(query_missing_file    "cannot open query file" ${CLI} ${Q} ${B}/no_such_queries.txt)
cli_failure(query_without_out     "--query and --query-out go together" ${CLI} ${D}/torus_1k.off --source-vertex 0 --query ${B}/queries_nan.txt)
cli_failure(isolines_zero         "iso-line count must be positive" ${CLI} ${D}/torus_1k.off --source-vertex 0 --isolines 0 ${OUTDIR}/i.txt)
cli_failure(isoline_values_bad    "iso-line value 'x' is not a finite number" ${CLI} ${D}/torus_1k.off --source-vertex 0 --isoline-values 0.1,x ${OUTDIR}/i.txt)
cli_failure(unwritable_refined    "cannot open" ${CLI} ${D}/torus_1k.off --source-vertex 0 --refined /nonexistent-dir/x.ply)

# The picture, decoded by libpng (not by our encoder): size and content.
add_executable(png_check ${CMAKE_CURRENT_SOURCE_DIR}/cli/png_check.cpp)
target_link_libraries(png_check PRIVATE PNG::PNG)
target_compile_options(png_check PRIVATE -Wall -Wextra ${GR_SANITIZE_FLAGS})
target_link_options(png_check PRIVATE ${GR_SANITIZE_FLAGS})
function(cli_png mesh)
  add_test(NAME cli.png.${mesh}
           COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DCHECK=$<TARGET_FILE:png_check> -DMESH=${D}/${mesh}.off
                   -DOUT=${OUTDIR}/png "-DEXTRA=${ARGN}" -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_png.cmake)
endfunction()
cli_png(torus_1k)
cli_png(eight --solver fmm)

# A mesh in several parts: the ridge of the source's, the others unreachable.
add_test(NAME cli.components.cube_and_octahedron
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DCHECK=$<TARGET_FILE:png_check> -DDATA=${B} -DOUT=${OUTDIR}/components
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_components.cmake)

# A surface with a border (one triangle): accepted, an empty ridge.
add_test(NAME cli.border.open_triangle COMMAND ${CLI} ${B}/open_triangle.off --source-vertex 0)

# Dirty input: every refusal that --repair would fix says so; with --repair,
# the repair is counted on stderr and every index in and out is the file's.
cli_failure(pinched_vertex        "vertex 0 is non-manifold .*\\(use --repair\\)$" ${CLI} ${B}/pinched.off --source-vertex 0)
cli_failure(range_grid_ply        "element 'range_grid' holds vertex-index lists" ${CLI} ${B}/range_grid.ply --source-vertex 0)
cli_failure_after_notes(source_vertex_removed "source vertex 2 was removed by the repair"
                        "repair: 1 isolated vertices removed" ${CLI} ${B}/cube_quads_isolated.off --repair --source-vertex 2)
cli_failure_after_notes(source_vertex_file_range "source vertex 9 is out of range: the mesh has 9 vertices"
                        "note: 6 polygons" ${CLI} ${B}/cube_quads_isolated.off --repair --source-vertex 9)
cli_failure_after_notes(query_quad_wrong_count "line 3: expected 'FACE' and 4 coordinates \\(face 0 has 4 vertices\\), got 4 fields"
                        "note: 6 polygons" ${CLI} ${B}/cube_quads.off --source-vertex 0 --query ${B}/queries_torus_1k_barycentric.txt
                        --query-barycentric --query-out ${OUTDIR}/q.txt)
# a vertex given twice: read with a seam (a slit: open), said in a note
cli_failure_after_notes(seam_note "source vertex 7 is out of range"
                        "note: 1 vertex is at the position of an earlier vertex: the surface is read open or in several parts there \\(--repair merges them\\)"
                        ${CLI} ${B}/octahedron_seam.off --source-vertex 7)
add_test(NAME cli.border.octahedron_seam COMMAND ${CLI} ${B}/octahedron_seam.off --source-vertex 4)
# a cube of quads with an isolated vertex inserted as vertex 2, against the cube
add_test(NAME cli.repair.isolated_vertex_and_quads
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DDIRTY=${B}/cube_quads_isolated.off -DDIRTY_SOURCE=5
                 -DCLEAN=${B}/cube_quads.off -DCLEAN_SOURCE=4 -DCLEAN_EXTRA=--repair
                 -DQUERIES=${B}/queries_cube_quads_points.txt -DBARYCENTRIC=${B}/queries_cube_quads_barycentric.txt
                 "-DNOTES=note: 6 polygons triangulated into 12 triangles; 0 not planar;repair: 1 isolated vertices removed"
                 -DOUT=${OUTDIR}/repair -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_repair.cmake)
# a pinched vertex, split: the source is the copy of the larger cone, which the
# clean file has as a vertex of its own
add_test(NAME cli.repair.pinched_vertex
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DDIRTY=${B}/pinched.off -DDIRTY_SOURCE=0
                 -DCLEAN=${B}/pinched_split.off -DCLEAN_SOURCE=1 -DQUERIES=${B}/queries_pinched_points.txt
                 "-DNOTES=repair: 1 non-manifold vertices split \\(1 vertex copies added\\);source vertex 0 was split by the repair into 2 copies; the source is the copy with the largest incident area"
                 -DOUT=${OUTDIR}/repair -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_repair.cmake)
# PLY triangle strips read as the faces they stand for, in strip order
add_test(NAME cli.repair.ply_triangle_strips
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DDIRTY=${B}/tetrahedron_strips.ply -DDIRTY_SOURCE=0
                 -DCLEAN=${B}/tetrahedron_strips_as_faces.off -DCLEAN_SOURCE=0 -DCLEAN_EXTRA=--repair
                 -DOUT=${OUTDIR}/repair -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_repair.cmake)
# a face reversed: the repair reverses it back (the fewer faces), as the clean file has it
add_test(NAME cli.repair.orientation
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DDIRTY=${B}/octahedron_flipped.off -DDIRTY_SOURCE=4
                 -DCLEAN=${B}/octahedron.off -DCLEAN_SOURCE=4 "-DNOTES=repair: 1 faces reoriented"
                 -DREORDERED_FACES=ON -DQUERIES=${B}/queries_octahedron_points.txt
                 -DOUT=${OUTDIR}/repair -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_repair.cmake)
# a degenerate face (a cap closing a T-junction): removed, the mesh then accepted
add_test(NAME cli.repair.degenerate_face
         COMMAND ${CMAKE_COMMAND} -DCLI=${CLI} -DDIRTY=${B}/octahedron_cap.off -DDIRTY_SOURCE=4
                 -DCLEAN=${B}/octahedron_cap.off -DCLEAN_SOURCE=4 -DCLEAN_EXTRA=--repair
                 "-DNOTES=repair: 1 degenerate faces removed" -DOUT=${OUTDIR}/repair_degenerate
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_repair.cmake)
cli_failure(degenerate_face       "face 9 is degenerate .*\\(use --repair\\)$" ${CLI} ${B}/octahedron_cap.off --source-vertex 4)

# SPDX-License-Identifier: GPL-3.0-or-later
# Runs geodesic_ridge --png and decodes the picture with libpng (png_check):
# its size must be 2*600 x 600 and it must show the ridge, the source, the
# background and many colours.
#   cmake -DCLI=prog -DCHECK=png_check -DMESH=file -DOUT=dir [-DEXTRA=...] -P expect_png.cmake
file(MAKE_DIRECTORY ${OUT})
get_filename_component(name ${MESH} NAME_WE)
string(REPLACE ";" "_" tag "${EXTRA}")
set(png ${OUT}/${name}${tag}.png)
file(REMOVE ${png})
execute_process(COMMAND ${CLI} ${MESH} --source-vertex 0 ${EXTRA} --png ${png}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "exit ${rc}\n${out}\n${err}")
endif()
execute_process(COMMAND ${CHECK} ${png} 1200 600 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${out}${err}")
endif()
message(STATUS "${out}")

# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a command that must fail with a non-zero exit and exactly one error line
# on stderr that matches EXPECT (a regular expression). Notes that come before
# it ("geodesic_ridge: note: ...", "geodesic_ridge: repair: ...": polygons
# triangulated, repairs done) are not errors; NOTES, if given, is a regular
# expression that they must match.
#   cmake -DEXPECT=regex [-DNOTES=regex] -DCOMMAND="prog;arg;..." -P expect_failure.cmake
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(notes "")
while(err MATCHES "^geodesic_ridge: (note|repair): [^\n]*\n")
  string(APPEND notes "${CMAKE_MATCH_0}")
  string(LENGTH "${CMAKE_MATCH_0}" n)
  string(SUBSTRING "${err}" ${n} -1 err)
endwhile()
if(DEFINED NOTES AND NOT notes MATCHES "${NOTES}")
  message(FATAL_ERROR "the notes do not match '${NOTES}':\n${notes}")
endif()
if(rc EQUAL 0)
  message(FATAL_ERROR "expected a failure, got exit 0\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "the program did not exit normally: ${rc}\nstderr: ${err}")
endif()
string(STRIP "${err}" err_stripped)
string(FIND "${err_stripped}" "\n" newline)
if(NOT newline EQUAL -1)
  message(FATAL_ERROR "expected a one-line error, got:\n${err}")
endif()
if(NOT err_stripped MATCHES "${EXPECT}")
  message(FATAL_ERROR "error message does not match '${EXPECT}':\n${err}")
endif()
message(STATUS "exit ${rc}: ${err_stripped}")

# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a command that must fail with a non-zero exit and exactly one line on
# stderr that matches EXPECT (a regular expression).
#   cmake -DEXPECT=regex -DCOMMAND="prog;arg;..." -P expect_failure.cmake
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
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

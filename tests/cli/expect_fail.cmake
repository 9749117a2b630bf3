# SPDX-License-Identifier: MIT
# Runs `hyst` with bad input and checks that it fails properly: non-zero exit,
# nothing on standard output, and a message on standard error matching EXPECT.
#   cmake -DTOOL=<hyst> -DARGS="fit|--degree|0|file" -DEXPECT=<regex> -P expect_fail.cmake
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND "${TOOL}" ${args}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
    message(FATAL_ERROR "exit status 0 for: hyst ${args}\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT out STREQUAL "")
    message(FATAL_ERROR "something printed as a result: '${out}'")
endif()
if(NOT err MATCHES "${EXPECT}")
    message(FATAL_ERROR "message does not match '${EXPECT}':\n${err}")
endif()
message(STATUS "exit ${rc}: ${err}")

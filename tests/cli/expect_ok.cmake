# SPDX-License-Identifier: MIT
# Runs `hyst` on good input and checks that it succeeds: exit status 0 and
# standard output matching EXPECT (standard error is shown, not checked).
#   cmake -DTOOL=<hyst> -DARGS="pi|--weights|1|file" -DEXPECT=<regex> -P expect_ok.cmake
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND "${TOOL}" ${args}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "exit status ${rc} for: hyst ${args}\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT out MATCHES "${EXPECT}")
    message(FATAL_ERROR "output does not match '${EXPECT}':\n${out}\nstderr: ${err}")
endif()
message(STATUS "exit 0: ${out}${err}")

# SPDX-License-Identifier: MIT
# ctest driver: installs hyst into a scratch prefix and builds + runs a consumer
# with find_package, or builds one that uses add_subdirectory.
# -DMODE=find_package|subdirectory -DHYST_SOURCE_DIR= -DHYST_BINARY_DIR= -DWORK_DIR=
file(REMOVE_RECURSE "${WORK_DIR}")
set(consumer_src "${CMAKE_CURRENT_LIST_DIR}/${MODE}")
function(run)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
    endif()
    message("${out}")
endfunction()
set(args "-DCMAKE_C_FLAGS=${CONSUMER_C_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_LINK_FLAGS}")
if(MODE STREQUAL "find_package")
    run(${CMAKE_COMMAND} --install "${HYST_BINARY_DIR}" --prefix "${WORK_DIR}/prefix")
    list(APPEND args "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix")
else()
    list(APPEND args "-DHYST_SOURCE_DIR=${HYST_SOURCE_DIR}")
endif()
run(${CMAKE_COMMAND} -S "${consumer_src}" -B "${WORK_DIR}/build" ${args})
run(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run("${WORK_DIR}/build/consumer")

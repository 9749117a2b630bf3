# SPDX-License-Identifier: MIT
# Size step of the size presets (m0-size, m7-size): injected into the hyst
# project with CMAKE_PROJECT_hyst_INCLUDE (the presets set it), so that the
# root CMakeLists.txt needs no size logic. Adds the target hyst_size, built
# by default after the library: it prints the text/data/bss of every object
# of libhyst.a and the libgcc float helpers it calls (tools/size_report).
#   cmake --preset m0-size && cmake --build --preset m0-size
# Also usable by hand: -DCMAKE_PROJECT_hyst_INCLUDE=<repo>/cmake/size_report.cmake
include_guard(GLOBAL)

find_package(Python3 COMPONENTS Interpreter)
find_program(HYST_SIZE_TOOL NAMES arm-none-eabi-size size)
if(NOT Python3_Interpreter_FOUND OR NOT HYST_SIZE_TOOL)
    message(WARNING "size_report.cmake: no Python 3 or no size program; no hyst_size step")
    return()
endif()
get_filename_component(_hyst_size_root "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
string(REGEX REPLACE "size$" "nm" _hyst_size_nm "${HYST_SIZE_TOOL}")

# The library target is defined after project(): add_dependencies and
# $<TARGET_FILE:hyst> are resolved at generate time.
add_custom_target(hyst_size ALL
    COMMAND "${Python3_EXECUTABLE}" "${_hyst_size_root}/tools/size_report"
            "$<TARGET_FILE:hyst>" --cpu "${HYST_CPU}"
            --size "${HYST_SIZE_TOOL}" --nm "${_hyst_size_nm}"
    COMMENT "hyst library sizes (${HYST_CPU})"
    VERBATIM)
add_dependencies(hyst_size hyst)

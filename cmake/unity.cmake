# SPDX-License-Identifier: MIT
# Provides the target `unity` (Unity 2.6.1, ThrowTheSwitch, MIT).
# Either -DUNITY_ROOT=<checkout> (a folder holding unity.c, or src/unity.c), or
# the pinned PyPI wheel vyperling==0.0.4, whose vyperling/c/ ships Unity 2.6.1:
# downloaded once into HYST_DEPS_DIR, unpacked, unity.c checked by SHA-256.
# Nothing of Unity is committed to this repository.
include_guard(GLOBAL)

set(UNITY_ROOT "" CACHE PATH "Unity checkout (folder with unity.c or src/unity.c); empty = pinned wheel")
set(HYST_DEPS_DIR "${PROJECT_SOURCE_DIR}/build/_deps" CACHE PATH "Download cache for test dependencies")
set(HYST_UNITY_WHEEL "vyperling==0.0.4")
set(HYST_UNITY_SHA256 "b90e735a54cf3b3765ab6caa955d11a1488ee73d9c6152cdc98576c2d17cb871")

function(hyst_fetch_unity out_dir)
    set(wheel_dir "${HYST_DEPS_DIR}/wheels")
    set(src_dir "${HYST_DEPS_DIR}/unity-2.6.1")
    if(NOT EXISTS "${src_dir}/unity.c")
        file(GLOB wheel "${wheel_dir}/vyperling-0.0.4-*.whl")
        if(NOT wheel)
            find_package(Python3 REQUIRED COMPONENTS Interpreter)
            message(STATUS "Unity: downloading ${HYST_UNITY_WHEEL} from PyPI")
            execute_process(
                COMMAND "${Python3_EXECUTABLE}" -m pip download --no-deps --quiet
                        --dest "${wheel_dir}" "${HYST_UNITY_WHEEL}"
                RESULT_VARIABLE rc)
            file(GLOB wheel "${wheel_dir}/vyperling-0.0.4-*.whl")
            if(NOT rc EQUAL 0 OR NOT wheel)
                message(FATAL_ERROR "Unity: pip download of ${HYST_UNITY_WHEEL} failed; "
                                    "pass -DUNITY_ROOT=<your Unity checkout> instead")
            endif()
        endif()
        set(unpack "${HYST_DEPS_DIR}/unpack")
        file(REMOVE_RECURSE "${unpack}")
        file(ARCHIVE_EXTRACT INPUT "${wheel}" DESTINATION "${unpack}" PATTERNS "vyperling/c/*")
        file(SHA256 "${unpack}/vyperling/c/unity.c" sha)
        if(NOT sha STREQUAL HYST_UNITY_SHA256)
            message(FATAL_ERROR "Unity: unity.c hash ${sha} != pinned ${HYST_UNITY_SHA256}")
        endif()
        file(MAKE_DIRECTORY "${src_dir}")
        foreach(f unity.c unity.h unity_internals.h UNITY_LICENSE)
            file(COPY "${unpack}/vyperling/c/${f}" DESTINATION "${src_dir}")
        endforeach()
        file(REMOVE_RECURSE "${unpack}")
    endif()
    set(${out_dir} "${src_dir}" PARENT_SCOPE)
endfunction()

if(NOT TARGET unity)
    if(UNITY_ROOT)
        if(EXISTS "${UNITY_ROOT}/src/unity.c")
            set(unity_src "${UNITY_ROOT}/src")
        elseif(EXISTS "${UNITY_ROOT}/unity.c")
            set(unity_src "${UNITY_ROOT}")
        else()
            message(FATAL_ERROR "UNITY_ROOT=${UNITY_ROOT} holds neither unity.c nor src/unity.c")
        endif()
    else()
        hyst_fetch_unity(unity_src)
    endif()
    add_library(unity STATIC "${unity_src}/unity.c")
    target_include_directories(unity SYSTEM PUBLIC "${unity_src}")
    target_compile_definitions(unity PUBLIC UNITY_INCLUDE_DOUBLE UNITY_SUPPORT_64 UNITY_INCLUDE_PRINT_FORMATTED)
    set_target_properties(unity PROPERTIES C_STANDARD 99 C_EXTENSIONS OFF)
    target_compile_options(unity PRIVATE -w)
endif()

# SPDX-License-Identifier: MIT
# The nm check (ctest "symbols"): the library archive must not reference the
# heap, stdio, process exit or assert, and must define no writable global data
# (no global state); its public functions are named hyst_*, and no static
# function name stands in two of its objects (the engine instantiated per
# variant generates names with the variant's prefix).
# Runs on the host for every preset, with the preset's nm
# (arm-none-eabi-nm for the Cortex-M4F build).
#   cmake -DNM=<nm> -DLIB=<libhyst.a> [-DLIB2=...] -P test_symbols.cmake
cmake_policy(SET CMP0057 NEW) # if(... IN_LIST ...)
set(forbidden
    malloc calloc realloc free aligned_alloc posix_memalign memalign valloc strdup
    sbrk _sbrk brk
    printf fprintf sprintf snprintf vprintf vfprintf vsprintf vsnprintf iprintf
    puts fputs putchar fputc putc fwrite fflush fopen fclose perror scanf sscanf
    stdin stdout stderr _impure_ptr
    exit _exit abort atexit __assert_fail __assert_func __assert signal raise
    time clock rand srand getenv)
set(status 0)
foreach(lib IN ITEMS ${LIB} ${LIB2})
    execute_process(COMMAND ${NM} ${lib} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "symbols: ${NM} ${lib} failed (${rc})")
    endif()
    string(REPLACE "\n" ";" lines "${out}")
    set(undefined "")
    set(defined_hyst 0)
    set(sanitized 0)
    set(statics "")
    set(twice "")
    foreach(line IN LISTS lines)
        if(line MATCHES "^ *U _?([A-Za-z0-9_.$]+)$")
            list(APPEND undefined ${CMAKE_MATCH_1})
            if(CMAKE_MATCH_1 MATCHES "^__(asan|ubsan|sanitizer)")
                set(sanitized 1)
            endif()
        elseif(line MATCHES "^[0-9a-fA-F]+ T _?hyst_")
            math(EXPR defined_hyst "${defined_hyst} + 1")
        endif()
        if(line MATCHES "^[0-9a-fA-F]+ t _?([A-Za-z_][A-Za-z0-9_]*)" AND
           NOT CMAKE_MATCH_1 MATCHES "^(sub_[DI]_|_GLOBAL_)") # sanitizer module constructors
            if(CMAKE_MATCH_1 IN_LIST statics)
                list(APPEND twice ${CMAKE_MATCH_1})
            endif()
            list(APPEND statics ${CMAKE_MATCH_1})
        elseif(line MATCHES "^[0-9a-fA-F]+ T _?([A-Za-z_][A-Za-z0-9_]*)" AND
               NOT CMAKE_MATCH_1 MATCHES "^hyst_")
            list(APPEND twice "${CMAKE_MATCH_1} (public, not hyst_*)")
        endif()
    endforeach()
    # Writable data (B/b bss, D/d data, C common, S/s small data); sanitizer
    # builds add their own bookkeeping data, so the check is skipped there.
    # Constant tables of function pointers (the curve kinds) land in
    # .data.rel.ro in position-independent code: read-only once loaded, not
    # state; nm's System V format names their section.
    execute_process(COMMAND ${NM} -f sysv ${lib} OUTPUT_VARIABLE sysv)
    string(REPLACE "\n" ";" sysv_lines "${sysv}")
    set(relro "")
    foreach(line IN LISTS sysv_lines)
        if(line MATCHES "^([A-Za-z_][A-Za-z0-9_.]*) *\\|.*\\| *\\.data\\.rel\\.ro")
            list(APPEND relro ${CMAKE_MATCH_1})
        endif()
    endforeach()
    set(writable "")
    if(NOT sanitized)
        foreach(line IN LISTS lines)
            if(line MATCHES "^[0-9a-fA-F]+ [BbDdCSsGg] (.+)$" AND NOT CMAKE_MATCH_1 IN_LIST relro)
                list(APPEND writable ${CMAKE_MATCH_1})
            endif()
        endforeach()
    endif()
    list(REMOVE_DUPLICATES undefined)
    set(bad "")
    foreach(sym IN LISTS forbidden)
        if(sym IN_LIST undefined)
            list(APPEND bad ${sym})
        endif()
    endforeach()
    list(JOIN undefined " " undefined_str)
    message(STATUS "symbols: ${lib}: ${defined_hyst} hyst_ functions; undefined: ${undefined_str}")
    if(defined_hyst LESS 5)
        message(SEND_ERROR "symbols: ${lib}: only ${defined_hyst} hyst_ functions found, nm output not understood")
        set(status 1)
    endif()
    if(bad)
        message(SEND_ERROR "symbols: ${lib} references forbidden symbols: ${bad}")
        set(status 1)
    endif()
    if(twice)
        list(REMOVE_DUPLICATES twice)
        message(SEND_ERROR "symbols: ${lib}: static functions in two objects, or unprefixed public ones: ${twice}")
        set(status 1)
    endif()
    if(writable)
        message(SEND_ERROR "symbols: ${lib} defines writable global data: ${writable}")
        set(status 1)
    endif()
endforeach()
if(status)
    message(FATAL_ERROR "symbols: FAILED")
endif()
message(STATUS "symbols: no heap, stdio, exit or assert references, no writable data")

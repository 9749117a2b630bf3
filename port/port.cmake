# SPDX-License-Identifier: MIT
# Selects the port that tests, benchmarks and examples link (never the core):
# sets HYST_PORT_TARGET. Included by the root CMakeLists.txt only when tests
# or benchmarks are built: a firmware that add_subdirectory()s hyst with
# both off gets the library and nothing else. Link the port target directly
# into each executable: the MPS2 port is an OBJECT library, whose objects do
# not pass through other libraries.
#
# HYST_PORT values:
#   host        the build machine (stdio, monotonic clock)
#   mps2-an385  QEMU MPS2 AN385, Cortex-M3 (port/mps2)
#   mps2-an386  QEMU MPS2 AN386, Cortex-M4F (port/mps2)
#   mps2-an500  QEMU MPS2 AN500, Cortex-M7 (port/mps2)
#   none        no port: the library (and the benchmark models) only
# Left empty, it follows the platform: host when building natively, the MPS2
# board of HYST_CPU with cmake/arm-none-eabi.cmake (HYST_QEMU_MACHINE), none
# for a core without one (Cortex-M0/M0+) or another cross toolchain.
include_guard(GLOBAL)

# The root CMakeLists.txt puts a platform default (mps2-an386 when cross
# compiling) in a normal variable when the cache entry is empty; the cache
# tells whether the user chose.
if("$CACHE{HYST_PORT}" STREQUAL "")
    if(NOT CMAKE_CROSSCOMPILING)
        set(HYST_PORT host)
    elseif(DEFINED HYST_QEMU_MACHINE)
        set(HYST_PORT "${HYST_QEMU_MACHINE}")
    else()
        set(HYST_PORT none)
    endif()
    if(HYST_PORT STREQUAL "")
        set(HYST_PORT none)
    endif()
endif()

set(_hyst_mps2_boards mps2-an385 mps2-an386 mps2-an500)
if(HYST_PORT IN_LIST _hyst_mps2_boards)
    # The board's CPU is fixed (QEMU refuses any other -cpu): the code must
    # be built for it.
    if(DEFINED HYST_QEMU_MACHINE AND NOT HYST_PORT STREQUAL HYST_QEMU_MACHINE)
        message(FATAL_ERROR "HYST_PORT=${HYST_PORT} does not run HYST_CPU=${HYST_CPU} "
            "code (that core's board: '${HYST_QEMU_MACHINE}'); leave HYST_PORT empty "
            "to follow HYST_CPU")
    endif()
    set(HYST_MPS2_BOARD "${HYST_PORT}")
    include(${CMAKE_CURRENT_LIST_DIR}/mps2/port.cmake)
    set(HYST_PORT_TARGET hyst_port_mps2)
elseif(HYST_PORT STREQUAL "host")
    add_library(hyst_port_host STATIC ${CMAKE_CURRENT_LIST_DIR}/host/hyst_port_host.c)
    target_include_directories(hyst_port_host PUBLIC ${CMAKE_CURRENT_LIST_DIR}
                                                     ${CMAKE_CURRENT_LIST_DIR}/host)
    set_target_properties(hyst_port_host PROPERTIES C_STANDARD 99 C_EXTENSIONS OFF)
    target_compile_options(hyst_port_host PRIVATE ${HYST_WARNING_FLAGS})
    set(HYST_PORT_TARGET hyst_port_host)
elseif(HYST_PORT STREQUAL "none")
    set(HYST_PORT_TARGET "")
    if(HYST_BUILD_TESTS)
        message(FATAL_ERROR "HYST_PORT=none (HYST_CPU=${HYST_CPU}): the tests and "
            "examples need a port; configure with -DHYST_BUILD_TESTS=OFF "
            "-DHYST_BUILD_BENCH=OFF to build the library alone")
    endif()
else()
    message(FATAL_ERROR "HYST_PORT=${HYST_PORT}: expected host, mps2-an385, mps2-an386, "
                        "mps2-an500 or none")
endif()

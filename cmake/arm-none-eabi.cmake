# SPDX-License-Identifier: MIT
# Toolchain: bare-metal Arm Cortex-M (arm-none-eabi-gcc, newlib). HYST_CPU
# picks the core; the tests run in the QEMU MPS2 machine of that core.
#   cmake -B build-m4 -DCMAKE_TOOLCHAIN_FILE=cmake/arm-none-eabi.cmake
#   cmake -B build-m3 -DCMAKE_TOOLCHAIN_FILE=cmake/arm-none-eabi.cmake -DHYST_CPU=cortex-m3
#
#   HYST_CPU       code generation                               QEMU machine
#   cortex-m0      -mcpu=cortex-m0 -mfloat-abi=soft              none (library only)
#   cortex-m0plus  -mcpu=cortex-m0plus -mfloat-abi=soft          none (library only)
#   cortex-m3      -mcpu=cortex-m3 -mfloat-abi=soft              mps2-an385
#   cortex-m4f     -mcpu=cortex-m4 -mfpu=fpv4-sp-d16 hard        mps2-an386 (default)
#   cortex-m7      -mcpu=cortex-m7 -mfpu=fpv5-d16 hard (double)  mps2-an500
#   cortex-m7sp    -mcpu=cortex-m7 -mfpu=fpv5-sp-d16 hard        mps2-an500
# All with -mthumb. The flags go into CMAKE_<LANG>_FLAGS_INIT, i.e. into the
# cache on the first configure: a build tree is for one core (changing
# HYST_CPU later is refused; use another build directory).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
# No crt0/syscalls during compiler checks: test-compile to a static lib.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(HYST_CPU cortex-m4f CACHE STRING
    "Target core: cortex-m0, cortex-m0plus, cortex-m3, cortex-m4f, cortex-m7, cortex-m7sp")
set_property(CACHE HYST_CPU PROPERTY STRINGS
    cortex-m0 cortex-m0plus cortex-m3 cortex-m4f cortex-m7 cortex-m7sp)
# The compiler checks run in their own projects, which read this file again:
# give them the same core.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES HYST_CPU)

# HYST_QEMU_MACHINE / HYST_QEMU_CPU: where the tests run (empty: nowhere).
# port/port.cmake takes the board of the same name.
if(HYST_CPU STREQUAL "cortex-m0" OR HYST_CPU STREQUAL "cortex-m0plus")
  set(_hyst_cpu "-mcpu=${HYST_CPU} -mfloat-abi=soft -mthumb")
  set(HYST_QEMU_MACHINE "")
  set(HYST_QEMU_CPU "")
elseif(HYST_CPU STREQUAL "cortex-m3")
  set(_hyst_cpu "-mcpu=cortex-m3 -mfloat-abi=soft -mthumb")
  set(HYST_QEMU_MACHINE mps2-an385)
  set(HYST_QEMU_CPU cortex-m3)
elseif(HYST_CPU STREQUAL "cortex-m4f")
  set(_hyst_cpu "-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard -mthumb")
  set(HYST_QEMU_MACHINE mps2-an386)
  set(HYST_QEMU_CPU cortex-m4)
elseif(HYST_CPU STREQUAL "cortex-m7")
  set(_hyst_cpu "-mcpu=cortex-m7 -mfpu=fpv5-d16 -mfloat-abi=hard -mthumb")
  set(HYST_QEMU_MACHINE mps2-an500)
  set(HYST_QEMU_CPU cortex-m7)
elseif(HYST_CPU STREQUAL "cortex-m7sp")
  set(_hyst_cpu "-mcpu=cortex-m7 -mfpu=fpv5-sp-d16 -mfloat-abi=hard -mthumb")
  set(HYST_QEMU_MACHINE mps2-an500)   # QEMU's M7 has the double FPU: a superset
  set(HYST_QEMU_CPU cortex-m7)
else()
  message(FATAL_ERROR "HYST_CPU=${HYST_CPU}: expected cortex-m0, cortex-m0plus, "
                      "cortex-m3, cortex-m4f, cortex-m7 or cortex-m7sp")
endif()

# The flags are cached by the first configure: a second core in the same
# tree would keep the first one's flags. (Only the main project has this
# entry; the compiler-check projects start from an empty cache.)
if(DEFINED CACHE{HYST_CPU_CONFIGURED} AND NOT "$CACHE{HYST_CPU_CONFIGURED}" STREQUAL HYST_CPU)
  message(FATAL_ERROR "HYST_CPU changed from $CACHE{HYST_CPU_CONFIGURED} to ${HYST_CPU} in "
                      "an existing build tree: configure a new build directory")
endif()
set(HYST_CPU_CONFIGURED "${HYST_CPU}" CACHE INTERNAL "HYST_CPU of this build tree")

set(CMAKE_C_FLAGS_INIT "${_hyst_cpu} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${CMAKE_C_FLAGS_INIT}")
set(CMAKE_ASM_FLAGS_INIT "${_hyst_cpu}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-Wl,--gc-sections")

# Look for libraries and headers in the toolchain's tree only, programs on
# the host. The ONLY modes need a root path, or they search the host: take
# the parent of newlib's lib/ (Debian: /usr/lib/arm-none-eabi).
execute_process(COMMAND ${CMAKE_C_COMPILER} -print-file-name=libc.a
  OUTPUT_VARIABLE _hyst_libc OUTPUT_STRIP_TRAILING_WHITESPACE)
if(IS_ABSOLUTE "${_hyst_libc}")
  get_filename_component(_hyst_root "${_hyst_libc}/../.." REALPATH)
  set(CMAKE_FIND_ROOT_PATH "${_hyst_root}")
endif()
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# add_test(COMMAND <exe target> ...) runs "<emulator> <elf>": -kernel must
# stay last so the ELF path lands on it. Semihosting carries the console
# and the exit status. Each MPS2 machine accepts only its own CPU (-cpu must
# match -M). Cortex-M0/M0+ have no MPS2 machine in QEMU: no emulator, no
# tests. A test that runs no timer computes the same without -icount, which
# slows QEMU down; one whose interrupts must land at the same instructions
# every run sets HYST_QEMU_ICOUNT_EMULATOR (-icount shift=0: one instruction
# per virtual nanosecond) as its CROSSCOMPILING_EMULATOR.
set(HYST_QEMU qemu-system-arm CACHE STRING "QEMU program for Arm system emulation")
if(HYST_QEMU_MACHINE)
  set(_hyst_qemu_run
    ${HYST_QEMU} -M ${HYST_QEMU_MACHINE} -cpu ${HYST_QEMU_CPU} -nographic -monitor none
    -serial none -semihosting-config enable=on,target=native)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${_hyst_qemu_run} -kernel)
  set(HYST_QEMU_ICOUNT_EMULATOR ${_hyst_qemu_run} -icount shift=0 -kernel)
endif()

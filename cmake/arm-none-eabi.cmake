# Toolchain: bare-metal Cortex-M4F (arm-none-eabi-gcc, newlib), tests run
# in QEMU mps2-an386.
#   cmake -B build-m4 -DCMAKE_TOOLCHAIN_FILE=cmake/arm-none-eabi.cmake
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
# No crt0/syscalls during compiler checks: test-compile to a static lib.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(_hyst_cpu "-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard -mthumb")
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
# and the exit status; -icount shift=0 makes timing deterministic.
set(HYST_QEMU qemu-system-arm CACHE STRING "QEMU program for Arm system emulation")
set(CMAKE_CROSSCOMPILING_EMULATOR
  ${HYST_QEMU} -M mps2-an386 -cpu cortex-m4 -nographic -monitor none
  -serial none -semihosting-config enable=on,target=native
  -icount shift=0 -kernel)

# SPDX-License-Identifier: MIT
# Toolchain: 8-bit AVR (avr-gcc, Debian gcc-avr + avr-libc), compile-only
# portability check of the core: 16-bit int, 16-bit size_t, and double is
# 32 bits there (double == float). Used by tools/portability.
#   cmake -B build/avr -DCMAKE_TOOLCHAIN_FILE=cmake/avr-gcc.cmake -DHYST_BUILD_TESTS=OFF
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR avr)
set(CMAKE_C_COMPILER avr-gcc)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(HYST_AVR_MCU atmega2560 CACHE STRING "AVR part for -mmcu")
# -ffreestanding: the core needs only the freestanding headers.
set(CMAKE_C_FLAGS_INIT "-mmcu=${HYST_AVR_MCU} -ffreestanding -ffunction-sections -fdata-sections")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)

# SPDX-License-Identifier: MIT
# Toolchain: bare-metal RISC-V (riscv64-unknown-elf-gcc, Debian
# gcc-riscv64-unknown-elf), compile-only portability check of the core for a
# 32-bit MCU with a single-precision FPU (rv32imafc/ilp32f; HYST_RISCV_ARCH
# and HYST_RISCV_ABI select others, e.g. rv64imafdc/lp64d). Used by tools/portability.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv)
set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(HYST_RISCV_ARCH rv32imafc CACHE STRING "-march")
set(HYST_RISCV_ABI ilp32f CACHE STRING "-mabi")
# -ffreestanding: the core needs only the freestanding headers (no libc).
set(CMAKE_C_FLAGS_INIT "-march=${HYST_RISCV_ARCH} -mabi=${HYST_RISCV_ABI} --specs=picolibc.specs -ffunction-sections -fdata-sections")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)

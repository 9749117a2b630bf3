# SPDX-License-Identifier: MIT
# Port for QEMU's MPS2 boards: mps2-an385 (Cortex-M3), mps2-an386
# (Cortex-M4F), mps2-an500 (Cortex-M7). Use with cmake/arm-none-eabi.cmake:
#   set(HYST_MPS2_BOARD mps2-an386)        # the QEMU machine; default an386
#   include(<repo>/port/mps2/port.cmake)
#   target_link_libraries(my_test PRIVATE hyst_port_mps2)
#
# One set of sources for every board (the boards share their memory map and
# the FPGAIO LED register), one linker script per board: mps2_<board>.ld
# defines the memory and includes mps2_sections.ld.
#
# An OBJECT library, not STATIC: nothing references the vector table or the
# newlib syscalls before libc is scanned, so an archive would drop them.
# Link it straight into each executable (objects do not propagate through
# an intermediate static library).
include_guard(GLOBAL)

set(_hyst_mps2_dir "${CMAKE_CURRENT_LIST_DIR}")
if(NOT HYST_MPS2_BOARD)
  set(HYST_MPS2_BOARD mps2-an386)
endif()
string(REPLACE "-" "_" _hyst_mps2_ld "${HYST_MPS2_BOARD}")
set(_hyst_mps2_ld "${_hyst_mps2_dir}/${_hyst_mps2_ld}.ld")
if(NOT EXISTS "${_hyst_mps2_ld}")
  message(FATAL_ERROR "port/mps2: no linker script for board ${HYST_MPS2_BOARD} "
                      "(expected ${_hyst_mps2_ld})")
endif()

add_library(hyst_port_mps2 OBJECT
  "${_hyst_mps2_dir}/startup.c"
  "${_hyst_mps2_dir}/semihost.c"
  "${_hyst_mps2_dir}/syscalls.c"
  "${_hyst_mps2_dir}/hyst_port_mps2.c")

# port/ holds the shared hyst_port.h contract.
target_include_directories(hyst_port_mps2 PUBLIC "${_hyst_mps2_dir}/..")
set_target_properties(hyst_port_mps2 PROPERTIES C_STANDARD 99
  C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
target_compile_options(hyst_port_mps2 PRIVATE
  -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror)

target_link_options(hyst_port_mps2 INTERFACE
  "-T${_hyst_mps2_ld}"
  "-L${_hyst_mps2_dir}"            # INCLUDE mps2_sections.ld
  -nostartfiles                    # startup.c replaces crt0
  --specs=nano.specs
  -Wl,-u,_printf_float             # nano printf drops %f unless asked
  -Wl,--gc-sections
  "-Wl,-Map=$<TARGET_PROPERTY:NAME>.map")

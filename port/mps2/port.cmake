# Port for QEMU mps2-an386 (Cortex-M4F). Use with cmake/arm-none-eabi.cmake:
#   include(<repo>/port/mps2-an386/port.cmake)
#   target_link_libraries(my_test PRIVATE hyst_port_mps2)
#
# An OBJECT library, not STATIC: nothing references the vector table or the
# newlib syscalls before libc is scanned, so an archive would drop them.
# Link it straight into each executable (objects do not propagate through
# an intermediate static library).
include_guard(GLOBAL)

set(_hyst_mps2_dir "${CMAKE_CURRENT_LIST_DIR}")

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
  "-T${_hyst_mps2_dir}/mps2_an386.ld"
  -nostartfiles                    # startup.c replaces crt0
  --specs=nano.specs
  -Wl,-u,_printf_float             # nano printf drops %f unless asked
  -Wl,--gc-sections
  "-Wl,-Map=$<TARGET_PROPERTY:NAME>.map")

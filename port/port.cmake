# Selects the port that tests, benchmarks and examples link (never the core):
# sets HYST_PORT_TARGET. Link it directly into each executable: the
# mps2-an386 port is an OBJECT library, whose objects do not pass through
# other libraries.
include_guard(GLOBAL)

if(HYST_PORT STREQUAL "mps2-an386")
    include(${CMAKE_CURRENT_LIST_DIR}/mps2-an386/port.cmake)
    set(HYST_PORT_TARGET hyst_port_mps2)
elseif(HYST_PORT STREQUAL "host")
    add_library(hyst_port_host STATIC ${CMAKE_CURRENT_LIST_DIR}/host/hyst_port_host.c)
    target_include_directories(hyst_port_host PUBLIC ${CMAKE_CURRENT_LIST_DIR}
                                                     ${CMAKE_CURRENT_LIST_DIR}/host)
    set_target_properties(hyst_port_host PROPERTIES C_STANDARD 99 C_EXTENSIONS OFF)
    target_compile_options(hyst_port_host PRIVATE ${HYST_WARNING_FLAGS})
    set(HYST_PORT_TARGET hyst_port_host)
else()
    message(FATAL_ERROR "HYST_PORT=${HYST_PORT}: expected host or mps2-an386")
endif()

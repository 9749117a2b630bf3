# SPDX-License-Identifier: MIT
# Per-sample instruction budgets of hyst_step on the Cortex-M4F:
# exact counts under QEMU, never time. Needs the bench_budget image
# (bench/CMakeLists.txt) and Python 3.
# Python by path, not the imported target: ctest would run a target through
# CMAKE_CROSSCOMPILING_EMULATOR.
option(HYST_BUDGET_TEST "Assert the per-sample instruction budgets under QEMU" ON)
# The product budgets, on the domain 0..4095 and on one across
# zero (-2048..2047: the keyed search's other ladder).
set(HYST_BUDGET_TYPICAL_INSNS 40)  # a sample that stays on its branch (measured: 35)
set(HYST_BUDGET_WORST_INSNS 150)   # any sample at Nu = 4096 (paper: ~420 DSP cycles)
# The compensator (HYST_INIT_INVERSE: the tabulated inverse of Eq. 20).
set(HYST_BUDGET_INV_TYPICAL_INSNS 50)  # measured: 42
set(HYST_BUDGET_INV_WORST_INSNS 160)   # measured: 156

if(HYST_BUDGET_TEST AND HYST_PORT STREQUAL "mps2-an386" AND TARGET bench_budget
   AND TARGET bench_budget_bipolar)
    find_package(Python3 COMPONENTS Interpreter)
    if(Python3_Interpreter_FOUND)
        add_test(NAME tcm_budget
                 COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/test_budget.py
                         --elf $<TARGET_FILE:bench_budget>
                         --elf $<TARGET_FILE:bench_budget_bipolar> --qemu ${HYST_QEMU} --nm ${CMAKE_NM}
                         --typical ${HYST_BUDGET_TYPICAL_INSNS}
                         --worst ${HYST_BUDGET_WORST_INSNS})
        set_tests_properties(tcm_budget PROPERTIES TIMEOUT 600 LABELS "budget")
        # One test per image: each runs its own QEMU (ctest -j runs them side by side).
        foreach(image bench_budget_inv bench_budget_inv_bipolar)
            if(TARGET ${image})
                string(REPLACE "bench_budget_inv" "inv_budget" test_name ${image})
                add_test(NAME ${test_name}
                         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/test_budget.py
                                 --elf $<TARGET_FILE:${image}> --qemu ${HYST_QEMU}
                                 --nm ${CMAKE_NM} --no-pi
                                 --typical ${HYST_BUDGET_INV_TYPICAL_INSNS}
                                 --worst ${HYST_BUDGET_INV_WORST_INSNS})
                set_tests_properties(${test_name} PROPERTIES TIMEOUT 900 LABELS "budget")
            endif()
        endforeach()
    else()
        message(WARNING "HYST_BUDGET_TEST: no Python 3, the budget test is not registered")
    endif()
endif()

# Per-sample instruction budgets of hyst_step on the Cortex-M4F (issue 5):
# exact counts under QEMU, never time. Needs the bench_budget image
# (bench/CMakeLists.txt) and Python 3.
# Python by path, not the imported target: ctest would run a target through
# CMAKE_CROSSCOMPILING_EMULATOR.
option(HYST_BUDGET_TEST "Assert the per-sample instruction budgets under QEMU" ON)
set(HYST_BUDGET_TYPICAL_INSNS 40)  # a sample that stays on its branch: the product budget (met: 35)
# Any sample at Nu = 4096. The product target is 150 (paper: ~420 DSP cycles)
# and is NOT met yet: the worst wipe-out measures 172 (11 probes of 5
# instructions + ~100 of slow path). This is a regression guard at the
# measured value, not the target; docs/timing.md says what would close the gap.
set(HYST_BUDGET_WORST_INSNS 172)

if(HYST_BUDGET_TEST AND HYST_PORT STREQUAL "mps2-an386" AND TARGET bench_budget)
    find_package(Python3 COMPONENTS Interpreter)
    if(Python3_Interpreter_FOUND)
        add_test(NAME tcm_budget
                 COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/test_budget.py
                         --elf $<TARGET_FILE:bench_budget> --qemu ${HYST_QEMU} --nm ${CMAKE_NM}
                         --typical ${HYST_BUDGET_TYPICAL_INSNS}
                         --worst ${HYST_BUDGET_WORST_INSNS})
        set_tests_properties(tcm_budget PROPERTIES TIMEOUT 600 LABELS "budget")
    else()
        message(WARNING "HYST_BUDGET_TEST: no Python 3, the budget test is not registered")
    endif()
endif()

# SPDX-License-Identifier: MIT
# Per-sample instruction budgets of hyst_step on the Cortex-M4F:
# exact counts under QEMU, never time. Needs the bench_budget image
# (bench/CMakeLists.txt) and Python 3.
# Python by path, not the imported target: ctest would run a target through
# CMAKE_CROSSCOMPILING_EMULATOR.
option(HYST_BUDGET_TEST "Assert the per-sample instruction budgets under QEMU" ON)
# The product budgets, on the domain 0..4095 and on one across
# zero (-2048..2047: the keyed search's other ladder).
set(HYST_BUDGET_TYPICAL_INSNS 35)  # a sample that stays on its branch (docs/results.md: tcm_typical_insns)
set(HYST_BUDGET_WORST_INSNS 145)   # any sample at Nu = 4096 (paper: ~420 DSP cycles)
# The compensator (HYST_INIT_INVERSE: the tabulated inverse of Eq. 20).
set(HYST_BUDGET_INV_TYPICAL_INSNS 45)
set(HYST_BUDGET_INV_WORST_INSNS 154)
# The asymmetric kind's tabulated compensator: its typical sample, and the
# compensators' worst-case goal it does not meet (printed, not asserted).
set(HYST_BUDGET_EVERETT_INV_TABLE_TYPICAL_INSNS 48)
set(HYST_GOAL_EVERETT_INV_TABLE_WORST_INSNS 160)
# The asymmetric kind (HYST_CURVE_EVERETT: Eq. 20 as an Everett function of
# degree 3 with a term in the loop's lower end) on the same trajectory: a
# slow sample derives the new branch's coefficients (docs/results.md:
# everett_*_insns*, everett4_*_insns* for E of degree 4 linear in t).
set(HYST_BUDGET_EVERETT_TYPICAL_INSNS 38)
set(HYST_BUDGET_EVERETT_WORST_INSNS 157)
# The asymmetric kind's solved compensator (Newton per branch, bracketed), the
# kind on a grid (6 intervals, a near step inside) and the grid's compensator
# (each branch's quadratic pieces solved): no product target, held at their
# figures so that no change makes them slower unseen (docs/results.md:
# everett_inv_*, everett_grid_*, everett_grid_inv_*).
set(HYST_BUDGET_EVERETT_INV_TYPICAL_INSNS 106)
set(HYST_BUDGET_EVERETT_INV_WORST_INSNS 331)
set(HYST_BUDGET_EVERETT_GRID_TYPICAL_INSNS 55)
set(HYST_BUDGET_EVERETT_GRID_WORST_INSNS 408)
set(HYST_BUDGET_EVERETT_GRID_INV_TYPICAL_INSNS 81)
set(HYST_BUDGET_EVERETT_GRID_INV_WORST_INSNS 737)
# The spline kind (16 intervals, a near step inside: its pieces on the fast
# path as the tabulated inverse's) and its compensator (each sample's piece
# by binary search, its cubic by Newton's iteration): held at their figures
# too (docs/results.md: spline_*, spline_inv_*).
set(HYST_BUDGET_SPLINE_TYPICAL_INSNS 45)
set(HYST_BUDGET_SPLINE_WORST_INSNS 154)
set(HYST_BUDGET_SPLINE_INV_TYPICAL_INSNS 333)
set(HYST_BUDGET_SPLINE_INV_WORST_INSNS 453)
# Its tabulated compensator (HYST_CURVE_SPLINE_INV_TABLE, the default 256
# intervals: cubic pieces of f0^-1 on the fast path, as the polynomial's
# compensator); its worst sample lands in one of the 5 intervals evaluated
# exactly (the spline's change of curvature at a knot bends f0^-1 beyond a
# cubic there), solved as the solved compensator solves every sample. Held at
# its figures too.
set(HYST_BUDGET_SPLINE_INV_TABLE_TYPICAL_INSNS 45)
set(HYST_BUDGET_SPLINE_INV_TABLE_WORST_INSNS 449)
# The q31 variant on the Cortex-M3 without an FPU (hyst/q31.h): the same
# trajectory at Nu = 4096 (docs/results.md: m3_q31_*_insns*).
set(HYST_BUDGET_Q31_TYPICAL_INSNS 45)
set(HYST_BUDGET_Q31_WORST_INSNS 149)
# Its compensator (HYST_Q31_INIT_INVERSE: the q31 tabulated inverse of
# Eq. 20, 32 intervals) on 4096 levels of the desired output.
set(HYST_BUDGET_Q31_INV_TYPICAL_INSNS 46)
set(HYST_BUDGET_Q31_INV_WORST_INSNS 146)

# hyst_budget_test(<name> <typical> <worst> <test_budget.py options...>)
function(hyst_budget_test name typical worst)
    find_package(Python3 COMPONENTS Interpreter)
    if(NOT Python3_Interpreter_FOUND)
        message(WARNING "HYST_BUDGET_TEST: no Python 3, ${name} is not registered")
        return()
    endif()
    add_test(NAME ${name}
             COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/test_budget.py
                     ${ARGN} --qemu ${HYST_QEMU} --nm ${CMAKE_NM}
                     --typical ${typical} --worst ${worst})
    set_tests_properties(${name} PROPERTIES TIMEOUT 600 LABELS "budget")
endfunction()

# The counting plugin against QEMU's instruction log (tools/qemu_count.py):
# the budgets below are counted with the plugin.
if(HYST_BUDGET_TEST AND HYST_PORT STREQUAL "mps2-an386" AND TARGET bench_tcm_linear)
    find_package(Python3 COMPONENTS Interpreter)
    if(Python3_Interpreter_FOUND)
        add_test(NAME qemu_count_methods
                 COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/test_qemu_count.py
                         --elf $<TARGET_FILE:bench_tcm_linear> --qemu ${HYST_QEMU})
        set_tests_properties(qemu_count_methods PROPERTIES TIMEOUT 300 LABELS "budget"
                             SKIP_RETURN_CODE 77)
    endif()
endif()
if(HYST_BUDGET_TEST AND HYST_PORT STREQUAL "mps2-an386" AND TARGET bench_budget
   AND TARGET bench_budget_bipolar)
    hyst_budget_test(tcm_budget ${HYST_BUDGET_TYPICAL_INSNS} ${HYST_BUDGET_WORST_INSNS}
                     --elf $<TARGET_FILE:bench_budget> --elf $<TARGET_FILE:bench_budget_bipolar>)
    # One test per compensator image: each runs its own QEMU (ctest -j runs them side by side).
    foreach(image bench_budget_inv bench_budget_inv_bipolar)
        if(TARGET ${image})
            string(REPLACE "bench_budget_inv" "inv_budget" test_name ${image})
            hyst_budget_test(${test_name} ${HYST_BUDGET_INV_TYPICAL_INSNS}
                             ${HYST_BUDGET_INV_WORST_INSNS} --elf $<TARGET_FILE:${image}> --no-pi)
            set_tests_properties(${test_name} PROPERTIES TIMEOUT 900)
        endif()
    endforeach()
    if(TARGET bench_budget_everett)
        hyst_budget_test(everett_budget ${HYST_BUDGET_EVERETT_TYPICAL_INSNS}
                         ${HYST_BUDGET_EVERETT_WORST_INSNS} --elf $<TARGET_FILE:bench_budget_everett> --no-pi)
    endif()
    # E of degree 4 linear in t (the identification's choice on the measured
    # record and on the report's plant), on both domains
    if(TARGET bench_budget_everett4 AND TARGET bench_budget_everett4_bipolar)
        hyst_budget_test(everett4_budget ${HYST_BUDGET_EVERETT_TYPICAL_INSNS}
                         ${HYST_BUDGET_EVERETT_WORST_INSNS} --elf $<TARGET_FILE:bench_budget_everett4>
                         --elf $<TARGET_FILE:bench_budget_everett4_bipolar> --no-pi)
    endif()
    foreach(image everett_inv everett_grid everett_grid_inv spline spline_inv spline_inv_table)
        if(TARGET bench_budget_${image})
            string(TOUPPER ${image} upper)
            hyst_budget_test(${image}_budget ${HYST_BUDGET_${upper}_TYPICAL_INSNS}
                             ${HYST_BUDGET_${upper}_WORST_INSNS}
                             --elf $<TARGET_FILE:bench_budget_${image}> --no-pi)
        endif()
    endforeach()
    if(TEST spline_inv_table_budget) # its init builds 256 intervals in soft double
        set_tests_properties(spline_inv_table_budget PROPERTIES TIMEOUT 900)
    endif()
    # Its tabulated compensator (the default table). The typical budget is asserted; the
    # worst is not met (everett_inv_table_worst_insns_nu4096: a slow sample derives the
    # branch's four rows and blends an interval on top of the forward kind's path,
    # docs/timing.md): printed against 160, not asserted.
    if(TARGET bench_budget_everett_inv_table)
        hyst_budget_test(everett_inv_table_budget ${HYST_BUDGET_EVERETT_INV_TABLE_TYPICAL_INSNS}
                         ${HYST_GOAL_EVERETT_INV_TABLE_WORST_INSNS}
                         --elf $<TARGET_FILE:bench_budget_everett_inv_table> --no-pi --worst-unmet)
        # its init builds the table in soft double: minutes counted from QEMU's log (the fallback)
        set_tests_properties(everett_inv_table_budget PROPERTIES TIMEOUT 1500)
    endif()
endif()
if(HYST_BUDGET_TEST AND HYST_PORT STREQUAL "mps2-an385" AND TARGET bench_q31)
    hyst_budget_test(q31_budget ${HYST_BUDGET_Q31_TYPICAL_INSNS} ${HYST_BUDGET_Q31_WORST_INSNS}
                     --elf $<TARGET_FILE:bench_q31> --no-pi)
    if(TARGET bench_q31_inv)
        hyst_budget_test(q31_inv_budget ${HYST_BUDGET_Q31_INV_TYPICAL_INSNS}
                         ${HYST_BUDGET_Q31_INV_WORST_INSNS} --elf $<TARGET_FILE:bench_q31_inv> --no-pi)
        set_tests_properties(q31_inv_budget PROPERTIES TIMEOUT 900)
    endif()
endif()

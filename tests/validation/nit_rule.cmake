rs_test(test_nit_rule validation SOURCES validation/test_nit_rule.c
        CASES nit_equals_mu_n levelling_at_high_load shear_soft_stack_misses_rule
              refused_without_g_rtheta)
target_compile_definitions(test_nit_rule PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

rs_test(test_study unit SOURCES unit/test_study.c
        CASES pareto_handcrafted plan_no_nip plan_contact_nip coarser_or_equal errors_by_hand default_time_least
              order_fit)
target_compile_definitions(test_study PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

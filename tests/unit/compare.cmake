rs_test(test_compare unit SOURCES unit/test_compare.c
        CASES wind_many_matches_single wind_many_failure_isolated run_names compare_layout)
target_compile_definitions(test_compare PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")

rs_test(test_lanes_linear validation SOURCES validation/test_lanes_linear.c
        CASES gauge_perturbation_linear)
target_compile_definitions(test_lanes_linear PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

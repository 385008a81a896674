rs_test(test_lanes_radius validation SOURCES validation/test_lanes_radius.c
        CASES newsprint_reel linear_stack entrained_air)
target_compile_definitions(test_lanes_radius PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

rs_test(test_lanes_drum validation SOURCES validation/test_lanes_drum.c
        CASES drum_drives_largest drum_uniform_equals_1d)
target_compile_definitions(test_lanes_drum PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

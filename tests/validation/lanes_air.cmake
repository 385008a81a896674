rs_test(test_lanes_air validation SOURCES validation/test_lanes_air.c
        CASES uniform_air_equals_1d band_ends_together)
target_compile_definitions(test_lanes_air PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

rs_test(test_lanes validation SOURCES validation/test_lanes.c
        CASES uniform_equals_1d tension_sum_every_layer stiff_stack_limit lane_count_convergence
              thick_band_runs_hard thin_lane_goes_slack roller_on_high_lanes)
target_compile_definitions(test_lanes PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

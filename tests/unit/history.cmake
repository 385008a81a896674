rs_test(test_history unit SOURCES unit/test_history.c
        CASES last_stage_is_final nan_above_outer_radius stage_is_shorter_run step_boundaries
              every_beyond_reel no_history memory_cap early_stop file_round_trip
              file_without_history)
target_compile_definitions(test_history PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

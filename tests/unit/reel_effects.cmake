rs_test(test_reel_effects unit SOURCES unit/test_reel_effects.c
        CASES list_holds_what_the_problem_has stepped_equals_wind driver_sets_tension
              ops_called_as_stated phase_sets_tension_and_load)
target_compile_definitions(test_reel_effects PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

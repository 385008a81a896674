rs_test(test_roll_state unit SOURCES unit/test_roll_state.c CASES rewind_is_exact nonfinite_keeps_roll)

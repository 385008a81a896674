rs_test(test_roll_layer unit SOURCES unit/test_roll_layer.c CASES fused_is_two_step quadratic_air lg2_series)

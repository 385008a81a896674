rs_test(test_roll_layer unit SOURCES unit/test_roll_layer.c CASES fused_is_two_step quadratic_air nonfinite_same nonfinite_hakiel lg2_series lg2_range
        lg2_range_same_roll)

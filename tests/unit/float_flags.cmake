rs_test(test_float_flags unit SOURCES unit/test_float_flags.c CASES special_values random_bits
        or_over_a_loop)

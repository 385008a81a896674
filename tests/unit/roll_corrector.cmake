rs_test(test_roll_corrector unit SOURCES unit/test_roll_corrector.c CASES selftest_passes selftest_catches_stale_norm
        fallback_small VALIDATION_CASES fallback_agrees fallback_agrees_lumped)

rs_test(test_taper validation SOURCES validation/test_taper.c CASES hoop_compression_ordering)

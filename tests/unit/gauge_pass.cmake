rs_test(test_gauge_pass unit SOURCES unit/test_gauge_pass.c CASES in_place_same)

rs_test(test_sundials_compat unit SOURCES unit/test_sundials_compat.c CASES cvode_error_recorded)

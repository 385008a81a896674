rs_test(test_status unit SOURCES unit/test_status.c CASES set_and_wrap exit_codes)

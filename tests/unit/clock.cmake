rs_test(test_clock unit SOURCES unit/test_clock.c CASES wall_monotonic thread_cpu)

# The CLI's progress estimate (src/cli/progress.c, compiled into the test: the CLI is not
# part of the library).
rs_test(test_progress unit SOURCES unit/test_progress.c ${PROJECT_SOURCE_DIR}/src/cli/progress.c
        CASES growing_cost_half_way constant_cost noisy_mixed_cost edges)

# The program's heap preparation (src/cli/heap.c, compiled into the test: the CLI is not
# part of the library).
rs_test(test_cli_heap unit SOURCES unit/test_cli_heap.c ${PROJECT_SOURCE_DIR}/src/cli/heap.c
        CASES marks_reserve blocks_from_reserve)

# The huge-page advice for the engine's large arrays (src/util/huge_pages.c).
rs_test(test_huge_pages unit SOURCES unit/test_huge_pages.c
        CASES advises_large_block small_block_left_alone)

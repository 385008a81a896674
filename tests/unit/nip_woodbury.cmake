rs_test(test_nip_woodbury unit SOURCES unit/test_nip_woodbury.c
        CASES solve_against_fresh_lu norm_and_estimate fallback_refused)

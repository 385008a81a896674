rs_test(test_nip_lemke unit SOURCES unit/test_nip_lemke.c
        CASES revised_equals_tableau solutions_satisfy_lcp)

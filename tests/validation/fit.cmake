rs_test(test_fit validation SOURCES validation/test_fit.c
        CASES recover_linear recover_pfeiffer recover_hakiel recover_table refuses)

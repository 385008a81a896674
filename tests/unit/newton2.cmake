rs_test(test_newton2 unit SOURCES unit/test_newton2.c CASES corrector_solves_residual exact_riccati_g5
        exact_riccati_g700 exact_one_rhs_per_step exact_no_root_recovers)

rs_test(test_newton2 unit SOURCES unit/test_newton2.c CASES riccati_g5 riccati_g700 one_jacobian_per_iteration
        setup_only_honoured)

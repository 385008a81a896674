rs_test(test_cylinder unit SOURCES unit/test_cylinder.c
        CASES engineering halfplane_isotropic lame_n0 betti_and_limit
              residual_isotropic residual_ortho_real residual_ortho_complex
              closed_sums parity accelerate_vs_plain tol_mode errors)

rs_test(test_cylinder unit SOURCES unit/test_cylinder.c
        CASES engineering halfplane_isotropic lame_n0 betti_and_limit
              residual_isotropic residual_ortho_real residual_ortho_complex
              parity shear_one_sweep rescale_halfplane_bound closed_sums_grid decoupled_mode errors
        # accuracy checks against 65,536-term plain sums: ~5 min each under valgrind
        VALIDATION_CASES closed_sums accelerate_vs_plain tol_mode)

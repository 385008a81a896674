rs_test(test_nip_contact validation SOURCES validation/test_nip_contact.c
        CASES equilibrium_center equilibrium_surface equilibrium_center_surface frictionless_center
              large_mu_full_stick friction_law_and_slip_zones thin_sheet_frictionless nit_bound
              rigid_cylinders_no_nit power_balance nit_levels_off stiff_sheet_full_slip rider_lcp
              lcp_ray_when_infeasible)
rs_test(test_nip_reel validation SOURCES validation/test_nip_reel.c
        CASES thin_roll_no_kink no_checkerboard convergence_in_M bad_input iteration_cap
              warm_equals_cold warm_search_along_reel stiff_drum_terms stiff_drum_rescaled
              single_precision_lu single_precision_fallback)

rs_test(test_hertz validation SOURCES validation/test_hertz.c
        CASES steel_steel rubber_steel profile_order_in_M terms_convergence thin_cover
              orthotropic_roll load_inverse)

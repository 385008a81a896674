rs_test(test_creep validation SOURCES validation/test_creep.c
        CASES proportional one_turn_hoop one_turn_radial bvp_vs_lekhnitskii converges_in_rtol
              storage_pressure_decays fails_cleanly scene_proportional)
# the cheap cases again as unit tests, so that valgrind runs the creep solver too
rs_test(test_creep_unit unit SOURCES validation/test_creep.c
        CASES one_turn_radial bvp_vs_lekhnitskii fails_cleanly)

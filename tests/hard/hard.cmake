# Hard cases (docs/robustness.md): the roll engine at the edges of its physics and
# numerics, one ctest entry per case, label hard.
rs_test(test_hard hard SOURCES hard/test_hard.c
        CASES soft_linear_g2_1e6 soft_linear_g2_1e8 soft_pfeiffer_g2_1e8 core_very_soft_limit
              core_stiff_soft_web thin_film_100k ratio_20)
rs_test(test_hard_load hard SOURCES hard/test_hard_load.c
        CASES tension_scaling_linear tension_limits_pfeiffer taper_through_zero hakiel_vs_table
              table_steep equilibrium_increment failure_keeps_finished)
# The contact nip at the edges of its physics and numerics (docs/robustness.md).
rs_test(test_hard_nip hard SOURCES hard/test_hard_nip.c
        CASES rubber_cover_099 friction_zero friction_two light_load_hertz light_load_winkler
              heavy_load complex_roots_continuity nodes_400)
rs_test(test_hard_nip_reel hard SOURCES hard/test_hard_nip_reel.c
        CASES taper_to_zero taper_t0_zero iteration_budget nip_failure_keeps_finished)

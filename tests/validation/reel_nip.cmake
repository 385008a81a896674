rs_test(test_reel_nip validation SOURCES validation/test_reel_nip.c
        CASES friction_adaptive_vs_every friction_curved_adaptive_vs_every contact_taper_last_interval contact_adaptive_vs_every
              every_k_layers)
target_compile_definitions(test_reel_nip PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

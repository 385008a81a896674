rs_test(test_roll validation SOURCES validation/test_roll.c
        CASES altmann_rigid altmann_elastic altmann_elastic_poisson altmann_rigid_hakiel
              altmann_elastic_hakiel one_layer_rigid outer_layer_hoop pfeiffer_vs_fd
              pfeiffer_vs_fd_hakiel converges_in_rtol converges_in_layers_per_step lumping_corrected
              g700_ratio10 reuse_vs_from_core)
rs_test(test_ring_statics validation SOURCES validation/test_ring_statics.c
        CASES ring_rigid ring_elastic ring_tube ring_hakiel paper_2000_published tube_400_sign
              thin_layer_limit)

# Storage after the winder (docs/storage.md, "What is verified")
rs_test(test_storage validation SOURCES validation/test_storage.c
        CASES core_expands_less core_expands_more anisotropic_rigid isotropic_g1
              matches_shooting_oracle equal_expansion_nothing driver_stages substeps_converge
              pet_heated_on_steel)

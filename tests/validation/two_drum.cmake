# The two-drum winder and the nip list, checked by hand (docs/nip.md, "Two-drum winders")
rs_test(test_two_drum validation SOURCES validation/test_two_drum.c
        CASES statics_by_hand weight_shared saturation_caps one_nip_list_bit_for_bit scene_checks)

# Speed effects: the centrifugal load (docs/validation.md, "Speed effects")
rs_test(test_spin validation SOURCES validation/test_spin.c
        CASES annulus_closed_form one_layer_rigid zero_speed speed_recipe updates_converge
              limit_refused)
# the limit T0 -> rho t V^2 on the hard suite too (refused cleanly, finite just above it)
rs_test(test_spin_hard hard SOURCES validation/test_spin.c CASES limit_refused)

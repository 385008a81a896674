rs_test(test_verdicts unit SOURCES unit/test_verdicts.c
        CASES starring_strength_and_zone starring_bonded_and_slipping slip_uniform_pressure
              ring_stack_in_tension_exact
              slip_inertia_torque slip_capstan_outermost verdict_scene_keys ring_stack_one_ring
        VALIDATION_CASES ring_single_layer_limit ring_stack_rigid_packet
                         ring_stack_scan_exact)
target_compile_definitions(test_verdicts PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")

rs_test(test_defects unit SOURCES unit/test_defects.c
        CASES hoop_no_compression hoop_one_layer hoop_ranges limits_absent zero_layers
              pressure_limit core_rating slip_capacity_formula slip_one_layer
              limits_from_scene
        VALIDATION_CASES buckling_critical_formula buckling_layered_stack_limit)
target_compile_definitions(test_defects PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")

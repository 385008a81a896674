rs_test(test_scene unit SOURCES unit/test_scene.c
        CASES load_all_cases contract_scene set_override web_length_formula defaults_filled
              material_lookup_order error_locations
              resolved_quoting)
target_compile_definitions(test_scene PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")

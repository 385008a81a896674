rs_test(test_scene_units unit SOURCES unit/test_scene_units.c
        CASES convert_exact split every_number_has_bounds bounds_documented plant_units
              bare_numbers wrong_dimension hard_bounds slip_warnings core_forms)
target_compile_definitions(test_scene_units PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")

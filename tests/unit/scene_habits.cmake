rs_test(test_scene_habits unit SOURCES unit/test_scene_habits.c
        CASES diameter_keys sizes_closed_form model_with_changes set_null_removes
              every_error_at_once drum_capacity_checked)
target_compile_definitions(test_scene_habits PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")

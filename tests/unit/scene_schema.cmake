rs_test(test_scene_schema unit SOURCES unit/test_scene_schema.c
        CASES schema_documented defaults_pass_checks)
target_compile_definitions(test_scene_schema PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")

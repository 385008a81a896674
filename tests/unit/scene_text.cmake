rs_test(test_scene_text unit SOURCES unit/test_scene_text.c
        CASES matches_file reads_len_bytes empty_and_null long_names)
target_compile_definitions(test_scene_text PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")

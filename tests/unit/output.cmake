rs_test(test_output unit SOURCES unit/test_output.c
        CASES round_trip zero_layers large_scene_text no_temp_left missing_directory not_a_regular_target
              readonly_directory failed_write_keeps_old_file)
rs_test(test_output_2d unit SOURCES unit/test_output_2d.c
        CASES chunked_2d_values chunked_2d_layout chunked_2d_grow chunk_shape_rule
              deflate_from_min_bytes)
# The test compares the version attribute with the generated header.
target_include_directories(test_output PRIVATE ${PROJECT_BINARY_DIR}/generated)

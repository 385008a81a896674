rs_test(test_output unit SOURCES unit/test_output.c
        CASES round_trip zero_layers large_scene_text no_temp_left missing_directory not_a_regular_target
              readonly_directory failed_write_keeps_old_file chunked_2d)
# The test compares the version attribute with the generated header.
target_include_directories(test_output PRIVATE ${PROJECT_BINARY_DIR}/generated)

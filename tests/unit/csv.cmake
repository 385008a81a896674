rs_test(test_csv unit SOURCES unit/test_csv.c CASES round_trip bad_directory nothing_half_written
              failed_write_keeps_old_files)
target_compile_definitions(test_csv PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")

rs_test(test_typed_access unit SOURCES unit/test_typed_access.c
        CASES lanes_arrays_are_the_fields lanes_absent_and_null storage_arrays_are_the_fields)
target_compile_definitions(test_typed_access PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

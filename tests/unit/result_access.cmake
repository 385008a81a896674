rs_test(test_result_access unit SOURCES unit/test_result_access.c
        CASES arrays_are_the_fields history_and_nip absent_and_null finite)
target_compile_definitions(test_result_access PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

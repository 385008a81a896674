rs_test(test_topweb validation SOURCES validation/test_topweb.c
        CASES diameter hoop_compression_no_starring)
target_compile_definitions(test_topweb PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")

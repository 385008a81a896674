rs_test(test_reader unit SOURCES unit/test_reader.c
        CASES run_file compare_file refuses_other_files shapes_and_missing children_order)

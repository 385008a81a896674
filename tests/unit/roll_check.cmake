rs_test(test_roll_check unit SOURCES unit/test_roll_check.c CASES holds_while_winding catches_broken
        holds_after_restore)

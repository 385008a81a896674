rs_test(test_lanes_share unit SOURCES unit/test_lanes_share.c
        CASES uniform slack_by_hand against_bisection refuses_bad_input)

rs_test(test_scene_limits unit SOURCES unit/test_scene_limits.c
        CASES aliases_bounded alias_cycle nesting_bounded nesting_through_alias size_bounded
              values_bounded keys_bounded aliases_within_limits
              largest_scene_loads)

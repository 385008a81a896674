rs_test(test_api_null unit SOURCES unit/test_api_null.c CASES scene_wind_null_out reel_wind_null null_set_entry)

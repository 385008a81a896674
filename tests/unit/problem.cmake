rs_test(test_problem unit SOURCES unit/test_problem.c CASES plain_reel friction_nip scene_accessors
                                                     no_scene)
target_compile_definitions(test_problem PRIVATE RS_TESTS_DIR="${CMAKE_CURRENT_SOURCE_DIR}")

rs_test(test_log_vec unit SOURCES unit/test_log_vec.c CASES random_normals near_one powers_and_ends
        loop_vectorised)

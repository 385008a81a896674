rs_test(test_error_correction validation SOURCES validation/test_error_correction.c CASES altmann_exact pfeiffer_tight innermost_hoop vanishes)
# a very soft web: the errors fall as rtol tightens; creep stages within rtol/50
rs_test(test_soft_web validation SOURCES validation/test_soft_web.c CASES soft_web_rtol creep_stages)
target_compile_definitions(test_soft_web PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")

rs_test(test_gauge validation SOURCES validation/test_gauge.c
        CASES strain_closed_forms annulus_closed_form shipped_by_hand wound_radius_history)
target_compile_definitions(test_gauge PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")

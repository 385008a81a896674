# The check harness (tests/check.h): a case that runs no check must fail, naming why.
add_executable(test_harness cli/test_harness.c)
target_include_directories(test_harness PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
add_test(NAME harness.no_check_fails
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect.sh 1
                 [[case no_check ran no check: a test that checks nothing cannot fail]]
                 -- $<TARGET_FILE:test_harness> no_check)
add_test(NAME harness.one_check_passes
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect.sh 0 [[1 checks, 0 failed]]
                 -- $<TARGET_FILE:test_harness> one_check)
set_tests_properties(harness.no_check_fails harness.one_check_passes PROPERTIES LABELS unit)

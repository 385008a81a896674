# reelsim plot with the real gnuplot (label cli: it runs an external program). The PNG
# checks decode the images with zlib (tests/png_check.h).
find_package(ZLIB REQUIRED)
rs_test(test_plot cli SOURCES cli/test_plot.c
        CASES rich_run plain_run odd_optional_groups compare_overlay empty_run refuses_bad_input
              gnuplot_missing_or_failing curve_failure_reported checker_sees_blank)
target_link_libraries(test_plot PRIVATE ZLIB::ZLIB)

# reelsim compare and reelsim plot on the command line (scripts take REELSIM SCENES CASE).
function(rs_cli_case name script case)
  add_test(NAME cli.${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/${script} $<TARGET_FILE:reelsim_cli>
                   ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes ${case}
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(cli.${name} PROPERTIES LABELS cli TIMEOUT 300)
endfunction()

foreach(c identical bad_scene solver_failure default_name missing_dir interrupted)
  rs_cli_case(compare_${c} compare.sh ${c})
endforeach()
foreach(c run_file compare_file no_gnuplot not_reelsim missing_dir not_dir bad_file_dir)
  rs_cli_case(plot_${c} plot.sh ${c})
endforeach()

set(SC ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes)
rs_cli_test(compare_help 0 [[usage: reelsim compare SCENE1 SCENE2]] compare --help)
rs_cli_test(compare_missing_scene 2 [[reelsim: compare: missing the scene file]] compare)
rs_cli_test(plot_help 0 [[usage: reelsim plot FILE\.h5]] help plot)
rs_cli_test(plot_missing_file_arg 2 [[reelsim: plot: missing the file]] plot -o .)
rs_cli_test(plot_no_such_file 2 [[reelsim: cannot open '.*no-such\.h5': No such file]]
            plot ${SC}/no-such.h5)
rs_cli_test(plot_not_hdf5 2 [[reelsim: '.*small\.yaml' is not an HDF5 file]]
            plot ${SC}/small.yaml)

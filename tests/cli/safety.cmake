# (named after cli.cmake, which defines rs_cli_script: the files are included in order)
# Attacks of issue 36 (docs/robustness.md, "Attacks and what they get"): what a hostile
# scene, file name or signal gets now. Each script's header says what it asserts.
set(SC ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes)
foreach(c run_title compare_names study_title)
  rs_cli_script(plot_inert_${c} plot_inert.sh ${SC}/small.yaml ${c})
endforeach()
# the atomic writer for every output: planted symlinks, stale temporaries
foreach(c optimize run sweep stale)
  rs_cli_script(atomic_symlink_${c} atomic_symlink.sh ${SC}/small.yaml ${c})
endforeach()
# SIGHUP (a closed terminal) and SIGQUIT are handled as SIGTERM: no temporaries, no file
set(CASES ${PROJECT_SOURCE_DIR}/cases)
rs_cli_script(run_hangup interrupt.sh ${CASES}/newsprint-rider.yaml HUP 129)
rs_cli_script(run_quit interrupt.sh ${CASES}/newsprint-rider.yaml QUIT 131)
rs_cli_script(study_hangup interrupt.sh ${CASES}/newsprint-rider.yaml HUP 129 study)
# plot: a signal stops gnuplot and removes the session's /tmp/reelsim-plot-* folder
rs_cli_script(plot_interrupted plot_interrupt.sh ${SC}/small.yaml INT 130)
rs_cli_script(plot_terminated plot_interrupt.sh ${SC}/small.yaml TERM 143)
rs_cli_script(plot_hangup plot_interrupt.sh ${SC}/small.yaml HUP 129)
# a bound on every size-like key (docs/scenes.md, "Limits")
rs_cli_test(bound_nip_terms 2 [[--set nip\.terms=99999999: at most 65536 series terms \(got 99999999]]
            check ${SC}/contact.yaml --set nip.terms=99999999)
rs_cli_test(bound_nip_nodes 2 [[--set nip\.nodes=5000: at most 512 nodes \(got 5000]]
            check ${SC}/contact.yaml --set nip.nodes=5000)
rs_cli_test(bound_max_steps 2 [[--set numerics\.max_steps=1000000000: at most 100000000 steps per increment]]
            check ${SC}/small.yaml --set numerics.max_steps=1000000000)
# where a run may write: input == output, a scene's own output.file, a failed --csv
foreach(c same_file escape csv_fails)
  rs_cli_script(run_outputs_${c} run_outputs.sh ${SC}/small.yaml ${c})
endforeach()
# Ctrl-C inside a long contact-nip solve (the largest nip.terms and nip.nodes allowed)
rs_cli_script(interrupt_nip_solve interrupt_nip.sh ${SC}/contact.yaml)
# sweep: a 1e12-run grid refused before the scene is loaded for its values (77 s before)
rs_cli_test(sweep_grid_1e12 2 [[--vary: the grid has more than 10000000 runs]]
            sweep ${SC}/small.yaml --vary winding.tension=100:200:1000000
            --vary core.radius=0.04:0.05:1000000 -o sweep-1e12.h5)
set_tests_properties(cli.sweep_grid_1e12 PROPERTIES TIMEOUT 10)
# control characters in titles printed escaped
rs_cli_script(title_escaped title_escaped.sh ${SC}/small.yaml)
# libyaml's reader errors (a NUL or a byte that is not UTF-8) at their own line and column
rs_cli_script(reader_error_line reader_line.sh ${SC}/small.yaml)

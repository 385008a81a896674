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

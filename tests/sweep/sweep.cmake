# The recipe search (src/sweep): its pieces in C, `reelsim sweep` from the command line.
#   rs_sweep_test(<exe> <label> SOURCES ... CASES ...): as rs_test, also linking reelsim_sweep
function(rs_sweep_test exe label)
  rs_test(${exe} ${label} ${ARGN})
  target_compile_definitions(${exe} PRIVATE RS_TEST_SCENES="${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes")
  target_link_libraries(${exe} PRIVATE reelsim_sweep reelsim_internal) # sweep before the library it calls
endfunction()

rs_sweep_test(test_sweep_vary unit SOURCES sweep/test_vary.c
  CASES app_error_record grid_values lists_and_ranges refusals checked_against_scene figures_of_a_run figure_names)

# --- reelsim sweep from the command line ------------------------------------------------
set(SWEEP_SCENE ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes/small.yaml)
foreach(c matches_runs grid_counts lhs_strata failed_run profiles plot interrupted
          plan_interrupted grid_terminated)
  add_test(NAME cli.sweep.${c}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/sweep/sweep.sh ${c} $<TARGET_FILE:reelsim_cli>
                   ${SWEEP_SCENE})
  set_tests_properties(cli.sweep.${c} PROPERTIES LABELS cli TIMEOUT 300)
endforeach()
# 3 ranks == 1 process. In a sanitizer build without LeakSanitizer: Open MPI leaves its own
# start-up allocations (its plugins) at exit, which are not reelsim's; ASan's checks of
# every access still run (docs/scale.md).
find_program(RS_MPIEXEC NAMES mpirun mpiexec)
if(RS_HAVE_MPI AND RS_MPIEXEC)
  add_test(NAME cli.sweep.mpi_same
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/sweep/sweep.sh mpi_same
                   $<TARGET_FILE:reelsim_cli> ${SWEEP_SCENE} ${RS_MPIEXEC})
  set_tests_properties(cli.sweep.mpi_same PROPERTIES LABELS "mpi;cli" TIMEOUT 300)
  if(REELSIM_SANITIZE)
    set_tests_properties(cli.sweep.mpi_same PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0")
  endif()
  # issue 36: a rank's failure, a different scene on a rank, a signal to any rank, a huge
  # plan, under mpirun -n 3 with each rank in its own folder (sweep.sh says what each asserts)
  foreach(c rank_fails scene_differs signal_worker signal_root signal_checking run_failed
            grid_1e12 module)
    add_test(NAME cli.sweep.mpi_${c}
             COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/sweep/sweep.sh mpi_${c}
                     $<TARGET_FILE:reelsim_cli> ${SWEEP_SCENE} ${RS_MPIEXEC})
    set_tests_properties(cli.sweep.mpi_${c} PROPERTIES LABELS "mpi;cli" TIMEOUT 300)
    if(REELSIM_SANITIZE)
      set_tests_properties(cli.sweep.mpi_${c} PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0")
    endif()
  endforeach()
endif()

# --- bad input: exit 2 naming the argument, nothing wound --------------------------------
set(SW sweep ${SWEEP_SCENE} -o sweep-bad.h5)
rs_cli_test(sweep.bad_unknown_key 2 [[--vary winding\.tensoin=1:2:3: --set winding\.tensoin=1: unknown key 'tensoin']]
            ${SW} --vary winding.tensoin=1:2:3)
rs_cli_test(sweep.bad_lo_above_hi 2 [[--vary winding\.tension=300:100:3: LO > HI]]
            ${SW} --vary winding.tension=300:100:3)
rs_cli_test(sweep.bad_n_zero 2 [[--vary winding\.tension=100:300:0: N must be >= 1]]
            ${SW} --vary winding.tension=100:300:0)
rs_cli_test(sweep.bad_malformed 2 [[--vary winding\.tension: expected KEY=LO:HI:N or KEY=V1,V2,\.\.\.]]
            ${SW} --vary winding.tension)
rs_cli_test(sweep.bad_range_without_n 2 [[--vary winding\.tension=100:300: expected LO:HI:N]]
            ${SW} --vary winding.tension=100:300)
rs_cli_test(sweep.bad_value 2 [[--vary winding\.tension=abc,200: .*winding\.tension.*not a number]]
            ${SW} --vary winding.tension=abc,200)
rs_cli_test(sweep.bad_refused_value 2 [[--vary core\.radius=0\.05,0\.08: .*final_radius: must be > the core radius]]
            ${SW} --vary core.radius=0.05,0.08)
rs_cli_test(sweep.bad_sample 2 [=[--sample lhs:0: R must lie in \[1, 10000000\]]=]
            ${SW} --vary winding.tension=100:300:3 --sample lhs:0)
rs_cli_test(sweep.bad_sample_word 2 [[--sample random: expected grid or lhs:R]]
            ${SW} --vary winding.tension=100:300:3 --sample random)
rs_cli_test(sweep.bad_no_vary 2 [[sweep: nothing to vary]] ${SW})
rs_cli_test(sweep.bad_twice 2 [[--vary winding\.tension=1,2: winding\.tension is already varied]]
            ${SW} --vary winding.tension=100:300:3 --vary winding.tension=1,2)
rs_cli_test(sweep.bad_threads 2 [=[--threads needs a number of threads in \[1, 256\]]=]
            ${SW} --vary winding.tension=100:300:3 --threads 0)

# reelsim plot of sweep and optimisation files, with the real gnuplot (label cli, as
# test_plot): the PNGs decoded (tests/png_check.h, zlib).
find_package(ZLIB REQUIRED)
rs_test(test_plot_sweep cli SOURCES sweep/test_plot_sweep.c
        CASES one_parameter two_parameters optimize_history)
target_link_libraries(test_plot_sweep PRIVATE ZLIB::ZLIB)

# reelsim optimize (src/sweep/optimize*.c, docs/optimize.md): its pieces in C, the command
# end to end (tests/optimize/optimize.sh: the linear roll's closed-form optimum, a
# nonlinear scene against a 5x5 grid, the inverse problem, refused arguments).
add_executable(test_optimize optimize/test_optimize.c)
target_include_directories(test_optimize PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(test_optimize PRIVATE reelsim_optimize reelsim_sweep reelsim_internal)
foreach(c constraints figures target_file target_refused misfit_closed_form history_file)
  add_test(NAME test_optimize.${c} COMMAND test_optimize ${c})
  set_tests_properties(test_optimize.${c} PROPERTIES LABELS unit TIMEOUT 300)
  if(RS_VALGRIND AND NOT REELSIM_SANITIZE)
    add_test(NAME valgrind.test_optimize.${c}
             COMMAND ${RS_VALGRIND} --quiet --error-exitcode=99 --leak-check=full
                     --errors-for-leak-kinds=definite,indirect --track-origins=yes
                     $<TARGET_FILE:test_optimize> ${c})
    set_tests_properties(valgrind.test_optimize.${c} PROPERTIES LABELS "valgrind" TIMEOUT 900)
  endif()
endforeach()

foreach(c linear nonlinear target bad_input infeasible failures interrupted)
  add_test(NAME cli.optimize_${c}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/optimize/optimize.sh $<TARGET_FILE:reelsim_cli>
                   ${CMAKE_CURRENT_SOURCE_DIR} ${c})
  set_tests_properties(cli.optimize_${c} PROPERTIES LABELS cli TIMEOUT 300)
endforeach()

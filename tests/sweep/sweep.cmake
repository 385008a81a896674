# The recipe search (src/sweep): its pieces in C, `reelsim sweep` from the command line.
#   rs_sweep_test(<exe> <label> SOURCES ... CASES ...): as rs_test, also linking reelsim_sweep
function(rs_sweep_test exe label)
  cmake_parse_arguments(T "" "" "SOURCES;CASES" ${ARGN})
  add_executable(${exe} ${T_SOURCES})
  target_include_directories(${exe} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_definitions(${exe} PRIVATE RS_TEST_SCENES="${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes")
  target_link_libraries(${exe} PRIVATE reelsim_sweep reelsim_internal)
  foreach(c IN LISTS T_CASES)
    add_test(NAME ${exe}.${c} COMMAND ${exe} ${c})
    set_tests_properties(${exe}.${c} PROPERTIES LABELS ${label} TIMEOUT 300)
    if(RS_VALGRIND AND label STREQUAL "unit" AND NOT REELSIM_SANITIZE)
      add_test(NAME valgrind.${exe}.${c}
               COMMAND ${RS_VALGRIND} --quiet --error-exitcode=99 --leak-check=full
                       --errors-for-leak-kinds=definite,indirect --track-origins=yes
                       $<TARGET_FILE:${exe}> ${c})
      set_tests_properties(valgrind.${exe}.${c} PROPERTIES LABELS "valgrind" TIMEOUT 900)
    endif()
  endforeach()
endfunction()

rs_sweep_test(test_sweep_vary unit SOURCES sweep/test_vary.c
  CASES grid_values lists_and_ranges refusals checked_against_scene figures_of_a_run figure_names)

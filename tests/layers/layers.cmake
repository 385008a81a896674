# The layer check (docs/architecture.md): the tree as it is, with the library's object files
# for call cycles, and one case per kind of violation on a small made-up tree.
add_test(NAME layers.tree
         COMMAND bash ${PROJECT_SOURCE_DIR}/scripts/check-layers.sh ${PROJECT_SOURCE_DIR}
                 $<TARGET_OBJECTS:reelsim_objects> $<TARGET_OBJECTS:reelsim_sweep>
                 $<TARGET_OBJECTS:reelsim_cli>
         COMMAND_EXPAND_LISTS)
set_tests_properties(layers.tree PROPERTIES LABELS unit TIMEOUT 900)
foreach(c lower_includes_higher internal_includes_higher include_cycle cli_internal_header
          unplaced call_cycle call_upwards)
  add_test(NAME layers.refuses.${c}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/layers/negative.sh ${c}
                   ${PROJECT_SOURCE_DIR}/scripts/check-layers.sh ${CMAKE_C_COMPILER})
  set_tests_properties(layers.refuses.${c} PROPERTIES LABELS unit TIMEOUT 300)
endforeach()

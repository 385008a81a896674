# The command line of every command (tests/cli/help.sh): help both ways listing every flag,
# unknown flags refused, --set KEY=VALUE and --set=KEY=VALUE alike.
foreach(c general run check compare plot study nip sweep)
  add_test(NAME cli.usage_${c}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/help.sh $<TARGET_FILE:reelsim_cli>
                   ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes ${c})
  set_tests_properties(cli.usage_${c} PROPERTIES LABELS cli TIMEOUT 300)
endforeach()
# source locations in messages only with --verbose (tests/cli/verbose.sh)
add_test(NAME cli.verbose_locations
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/verbose.sh $<TARGET_FILE:reelsim_cli>
                 ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes)
set_tests_properties(cli.verbose_locations PROPERTIES LABELS cli TIMEOUT 300)

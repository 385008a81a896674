# reelsim study (docs/accuracy.md): a quick study on small scenes, end to end (tests/cli/study.sh)
foreach(c small_quick nip_quick bad_input not_dir usage)
  add_test(NAME cli.study_${c}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/study.sh $<TARGET_FILE:reelsim_cli>
                   ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes ${c})
  set_tests_properties(cli.study_${c} PROPERTIES LABELS cli TIMEOUT 300)
endforeach()
# SIGINT and SIGTERM stop a study the way they stop a run: nothing written, no directory
rs_cli_script(study_interrupted interrupt.sh ${PROJECT_SOURCE_DIR}/cases/newsprint-rider.yaml INT 130 study)
rs_cli_script(study_terminated interrupt.sh ${PROJECT_SOURCE_DIR}/cases/newsprint-rider.yaml TERM 143 study)

# A new user's habits (issue 19): sizes as diameters, the summary's sizes, a model with
# changes, --set KEY=null.
rs_cli_script(summary_sizes summary_lines.sh
              [[^  final radius +318\.0 mm$]]
              [[^  diameter +627\.0 mm \(free r_c \+ N t: 636\.0 mm; the stack compressed, what a gauge reads\)$]]
              [[^  wound length +3000\.2 m \(the layers' circumferences at mid-thickness\)$]]
              [[^  roll mass +417\.03 kg per metre of width$]]
              -- run ${CASES}/pet-topweb.yaml -o summary-sizes.h5)
rs_cli_test(core_radius_and_diameter 2
            [[--set core\.diameter=0\.2: give either core\.radius or core\.diameter, not both]]
            check ${CASES}/newsprint-rider.yaml --set core.diameter=0.2)
rs_cli_test(final_radius_and_diameter 2
            [[--set winding\.final_diameter=1: give either winding\.final_radius or winding\.final_diameter, not both]]
            check ${CASES}/newsprint-rider.yaml --set winding.final_diameter=1)
rs_cli_test(set_null_switches_size 0 [[roll: 76\.2 -> 342\.367 mm, 3802 layers \(web length 5000 m\)]]
            check ${CASES}/newsprint-rider.yaml --set winding.final_radius=null
            --set winding.web_length=5000)
rs_cli_test(model_with_changes 0
            [[material: pet-film from .*models/pet-film\.yaml \(caliper 50 um, E_theta = 4\.5e9 Pa]]
            check ${SC}/pet-50um.yaml)
rs_cli_test(model_with_changes_diameter 0 [[roll: 76\.2 -> 100 mm, 476 layers]]
            check ${SC}/pet-50um.yaml)
# run --json and compare --json, parsed by Python (docs/cli.md, "JSON").
rs_cli_script(json_summary json_summary.sh ${SC}/small.yaml ${CASES}/pet-topweb.yaml)
# A --set value that is not UTF-8 (the shell passes any bytes): bad input, not an
# internal error of the YAML writer.
rs_cli_script(set_not_utf8 not_utf8.sh ${SC}/small.yaml)
# compare prints each run's defect verdicts under its table.
rs_cli_script(compare_verdicts summary_lines.sh
              [[^defect risk +hoop stress +starring +pressure +slip +core$]]
              [[^1-small +ok +ok +not assessed +not assessed +not assessed$]]
              [[^2-pet-topweb +present +ok +not assessed +not assessed +not assessed$]]
              -- compare ${SC}/small.yaml ${CASES}/pet-topweb.yaml -o compare-verdicts.h5)
# Every error of a scene at once, one line each (docs/scenes.md, "Errors").
rs_cli_script(all_errors all_errors.sh ${SC}/many-errors.yaml)
# run --csv exports the history stages; plot draws a study file.
rs_cli_script(history_csv history_csv.sh ${SC}/small.yaml)
rs_cli_script(plot_study plot_study.sh ${SC}/small.yaml)
set_tests_properties(cli.plot_study PROPERTIES SKIP_RETURN_CODE 77)
# bash completion, generated from the option table at build time and installed
rs_cli_script(completion completion.sh ${PROJECT_BINARY_DIR}/reelsim.bash)
rs_cli_script(json_storage json_storage.sh ${CASES}/pet-storage.yaml)

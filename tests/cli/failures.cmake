# Runs that cannot finish (docs/robustness.md): each says exactly why and where, exits
# with its status, and leaves no file under the output name unless --keep-partial asks.
# fails.sh REELSIM STATUS REGEX... -- ARGS (also: no NaN/Inf printed, nothing written).
function(rs_cli_fails name status)
  add_test(NAME cli.${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/fails.sh $<TARGET_FILE:reelsim_cli> ${status}
                   ${ARGN}
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(cli.${name} PROPERTIES LABELS cli TIMEOUT 300 SKIP_RETURN_CODE 77)
endfunction()

rs_cli_fails(fail_max_steps 3
  [[solver failure: winding layers 2-2 of 200 \(r = 0\.0502 m\): CVODE needed more than 2 steps to cross the roll \(reached r = 0\.05[0-9]* m of 0\.0501 m\); raise numerics\.max_steps or loosen numerics\.rtol]]
  [[^reelsim:   1 of 200 layers were wound; no output written$]]
  -- ${SC}/small.yaml --set numerics.max_steps=2 --set numerics.rtol=1e-5)
rs_cli_fails(fail_max_steps_mid_roll 3
  [[solver failure: winding layers ([0-9]+)-[0-9]+ of 200 \(r = 0\.0[56][0-9]+ m\): CVODE needed more than 30 steps]]
  [[^reelsim:   [1-9][0-9]* of 200 layers were wound; no output written$]]
  -- ${SC}/small.yaml --set numerics.max_steps=30 --set numerics.rtol=1e-5)
rs_cli_fails(fail_radial_modulus_negative 3
  [[solver failure: winding layers [0-9]+-[0-9]+ of 200 \(r = 0\.05[0-9]* m\): radial modulus E_r = -[0-9.e+]+ Pa at r = 0\.05[0-9]* m \(pressure [0-9.e+]+ Pa\) is not positive: the radial law is outside its range]]
  [[^reelsim:   [1-9][0-9]* of 200 layers were wound; no output written$]]
  -- ${SC}/hakiel-negative.yaml)
rs_cli_fails(fail_taper_negative 2
  [[bad-taper\.yaml:9: winding\.tension\.end: taper makes the tension negative]]
  -- ${SC}/bad-taper.yaml)
rs_cli_test(run_taper_to_zero 0 [[wound-on tension +0\.0 \.\. 199\.[0-9] N/m]]
            run ${SC}/taper-zero.yaml -o taper-zero.h5)

rs_cli_script(keep_partial_solver keep_partial.sh ${SC}/small.yaml --set numerics.max_steps=30
              --set numerics.rtol=1e-5)
rs_cli_script(keep_partial_radial keep_partial.sh ${SC}/hakiel-negative.yaml)
rs_cli_script(run_terminated interrupt.sh ${CASES}/newsprint-rider.yaml TERM 143)
rs_cli_script(run_interrupted_keep_partial interrupt.sh ${CASES}/newsprint-rider.yaml INT 130
              --keep-partial)
rs_cli_script(disk_full_fsize disk_full.sh ${SC}/small.yaml fsize)
rs_cli_script(disk_full_readonly disk_full.sh ${SC}/small.yaml readonly)
set_tests_properties(cli.disk_full_readonly PROPERTIES SKIP_RETURN_CODE 77)
rs_cli_test(keep_partial_check_refused 2 [[check: --keep-partial only applies to run]]
            check ${SC}/small.yaml --keep-partial)
# the drum cannot carry the rising tension part-way: known before winding, so refused by
# check and run alike (exit 2, nothing wound), naming the keys and the radius. (The reel's
# own refusal part-way, exit 3, is for problems made without a scene:
# test_hard_nip_reel.nip_failure_keeps_finished.)
rs_cli_test(fail_drum_check 2
  [[drum-midrun\.yaml:[0-9]+: nip\.friction\.drum: the drum cannot carry the web by friction from roll radius r = 0\.08[0-9]* m \(layer [0-9]+ of 169\) on: nip\.friction\.drum x nip\.load = 0\.35 x 1750 = 612\.5 N/m is not above winding\.tension = 61[0-9.]+ N/m, all of which the drum carries on a surface winder]]
  check ${SC}/drum-midrun.yaml)
rs_cli_script(fail_drum_run_no_file no_output.sh 2 ${SC}/drum-midrun.yaml)

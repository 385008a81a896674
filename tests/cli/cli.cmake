# reelsim command line: exit statuses and messages (tests/cli/expect.sh).
# Every bad-input class exits 2 with "FILE:LINE: key.path: why" (or "--set ...: why").
set(SC ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes)
set(CASES ${PROJECT_SOURCE_DIR}/cases)

# --- bad scenes: one per class of input error --------------------------------------
rs_cli_test(bad_unknown_key 2 [[bad-key\.yaml:4: core\.radus: unknown key 'radus' \(expected one of: radius, stiffness, bore, modulus, poisson, rating, alpha, beta, diameter, inner_diameter, wall\)]]
            check ${SC}/bad-key.yaml)
rs_cli_test(bad_wrong_type 2 [[bad-type\.yaml:3: material\.caliper: not a number \(got 'abc'\)]]
            check ${SC}/bad-type.yaml)
rs_cli_test(bad_missing_key 2 [[missing-key\.yaml:4: winding\.tension: required key is missing]]
            check ${SC}/missing-key.yaml)
rs_cli_test(bad_caliper 2 [[bad-caliper\.yaml:4: material\.caliper: must be > 0 m \(got -7e-05\)]]
            check ${SC}/bad-caliper.yaml)
rs_cli_test(bad_model_caliper 2 [[scenes/models/badmodel\.yaml:4: caliper: must be > 0 m \(got -7e-05\)]]
            check ${SC}/bad-model.yaml)
rs_cli_test(bad_no_model 2 [[bad-no-model\.yaml:2: material: no material model 'unobtainium']]
            check ${SC}/bad-no-model.yaml)
rs_cli_test(bad_final_radius 2 [[bad-radius\.yaml:5: winding\.final_radius: must be > the core radius 0\.0762 m]]
            check ${SC}/bad-radius.yaml)
rs_cli_test(bad_modulus 2 [[bad-modulus\.yaml:4: material\.E_theta: must be > 0 Pa]]
            check ${SC}/bad-modulus.yaml)
rs_cli_test(bad_radial_law 2 [[bad-radial\.yaml:7: material\.radial\.K1: must be > 0 Pa]]
            check ${SC}/bad-radial.yaml)
rs_cli_test(bad_friction 2 [[bad-friction\.yaml:8: nip\.friction\.roll: must be >= 0 \(got -0\.19\)]]
            check ${SC}/bad-friction.yaml)
rs_cli_test(bad_radial_table 2 [[bad-table\.yaml:10: material\.radial\.points\[2\]: must be sorted]]
            check ${SC}/bad-table.yaml)
rs_cli_test(bad_tension_table 2 [[bad-tension-table\.yaml:10: winding\.tension\.table\[2\]: table must be sorted]]
            check ${SC}/bad-tension-table.yaml)
rs_cli_test(bad_taper 2 [[bad-taper\.yaml:9: winding\.tension\.end: taper makes the tension negative at r = 0\.5 m \(-50 N/m\)]]
            check ${SC}/bad-taper.yaml)
rs_cli_test(bad_nip_load 2 [[bad-load\.yaml:7: nip\.load\.k: taper makes the nip load negative]]
            check ${SC}/bad-load.yaml)
rs_cli_test(bad_torque_end 2 [[bad-torque-end\.yaml:6: winding\.tension\.end: a torque recipe is fixed by its start value]]
            check ${SC}/bad-torque-end.yaml)
rs_cli_test(bad_core_bore 2 [[bad-bore\.yaml:3: core\.bore: must be >= 0 and < core\.radius]]
            check ${SC}/bad-bore.yaml)
rs_cli_test(bad_core_poisson 2 [[bad-poisson\.yaml:3: core\.poisson: must lie in \(-1, 0\.5\)]]
            check ${SC}/bad-poisson.yaml)
rs_cli_test(bad_drum 2 [[bad-drum\.yaml:9: nip\.drum\.radius: must be > nip\.drum\.core_radius]]
            check ${SC}/bad-drum.yaml)
rs_cli_test(bad_nodes 2 [[bad-nodes\.yaml:10: nip\.nodes: must be >= 3 \(got 2\)]]
            check ${SC}/bad-nodes.yaml)
rs_cli_test(bad_not_finite 2 [[bad-infinite\.yaml:4: material\.E_theta: must be a finite number]]
            check ${SC}/bad-infinite.yaml)
rs_cli_test(bad_yaml_syntax 2 [[bad-syntax\.yaml:4: YAML syntax error]]
            check ${SC}/bad-syntax.yaml)
rs_cli_test(bad_duplicate_key 2 [[bad-duplicate\.yaml:5: core: duplicate key 'core']]
            check ${SC}/bad-duplicate.yaml)
rs_cli_test(bad_run_input 2 [[bad-caliper\.yaml:4: material\.caliper]]
            run ${SC}/bad-caliper.yaml -o bad-run-input.h5)

# --- --set ----------------------------------------------------------------------------
rs_cli_test(set_bad_path 2 [[--set core\.radus=1: unknown key 'radus' in core]]
            check ${CASES}/newsprint-rider.yaml --set core.radus=1)
rs_cli_test(set_bad_value 2 [[--set numerics\.rtol=abc: not a number]]
            check ${CASES}/newsprint-rider.yaml --set numerics.rtol=abc)
rs_cli_test(set_bad_rtol 2 [[--set numerics\.rtol=0: must lie in \(0, 1\)]]
            check ${CASES}/newsprint-rider.yaml --set numerics.rtol=0)
rs_cli_test(set_bad_layers_per_step 2 [[--set numerics\.layers_per_step=0: must be >= 1]]
            check ${CASES}/newsprint-rider.yaml --set numerics.layers_per_step=0)
rs_cli_test(set_not_scalar 2 [[--set core=1: core is a mapping, not a single value]]
            check ${CASES}/newsprint-rider.yaml --set core=1)
rs_cli_test(set_malformed 2 [[--set winding\.tension: expected key\.path=value]]
            check ${CASES}/newsprint-rider.yaml --set winding.tension)
rs_cli_test(set_creates_key 0 [[numerics: 10 layers per step]]
            check ${CASES}/newsprint-taper.yaml --set numerics.layers_per_step=10)
rs_cli_test(reuse_default 0 [[numerics: 1 layer per step, rtol 1e-6, deep solution reused]]
            check ${CASES}/newsprint-rider.yaml)
rs_cli_test(reuse_none 0 [[rtol 1e-6, every increment integrated from the core]]
            check ${CASES}/newsprint-rider.yaml --set numerics.reuse=none)
rs_cli_test(reuse_bad 2 [[--set numerics\.reuse=bogus: unknown value 'bogus' \(expected one of: deep, none, first-order\)]]
            check ${CASES}/newsprint-rider.yaml --set numerics.reuse=bogus)
rs_cli_test(set_table_entry 0 [=[table: \[\[0\.0762, 800\], \[0\.3, 320\], \[0\.5, 600\]\]]=]
            check ${CASES}/linerboard-table.yaml --set winding.tension.table[1][1]=320)
rs_cli_test(set_table_negative 2 [[--set winding\.tension\.table\.2\.1=-5: the tension must not be negative]]
            check ${CASES}/linerboard-table.yaml --set winding.tension.table.2.1=-5)
rs_cli_test(set_material 0 [[material: pet-film from .*models/pet-film\.yaml]]
            check ${CASES}/newsprint-rider.yaml --set material=pet-film)

# --- usage ---------------------------------------------------------------------------------
rs_cli_test(unknown_command 2 [[reelsim: unknown command 'frobnicate']] frobnicate)
rs_cli_test(unknown_option 2 [[reelsim: run: unknown option '--frob']]
            run --frob ${CASES}/newsprint-rider.yaml)
rs_cli_test(missing_scene_arg 2 [[reelsim: run: missing the scene file]] run)
rs_cli_test(missing_scene_file 2 [[reelsim: .*does-not-exist\.yaml: cannot open]]
            check ${SC}/does-not-exist.yaml)
rs_cli_test(no_arguments 2 [[usage: reelsim <command>]])
rs_cli_test(version 0 [[^reelsim [0-9]+\.[0-9]+\.[0-9]+$]] --version)
rs_cli_test(help 0 [[usage: reelsim <command>]] --help)
rs_cli_test(help_run 0 [[usage: reelsim run SCENE]] help run)
rs_cli_test(run_help 0 [[usage: reelsim run SCENE]] run --help)
rs_cli_test(check_help 0 [[usage: reelsim check SCENE]] check --help)

# --- check on good scenes -----------------------------------------------------------------
rs_cli_test(check_rider 0 [[nip: friction \(T0 = T \+ 0\.19 N\)]]
            check ${CASES}/newsprint-rider.yaml)
rs_cli_test(check_rider_core 0 [[core: elastic \(E_c = 1e9 Pa\)]]
            check ${CASES}/newsprint-rider.yaml)
rs_cli_test(check_rider_radial 0 [[radial law: pfeiffer \(K1 = 5000 Pa, K2 = 60\)]]
            check ${CASES}/newsprint-rider.yaml)
rs_cli_test(check_taper 0 [[tension: hyperbolic taper 350 -> 280 N/m]]
            check ${CASES}/newsprint-taper.yaml)
rs_cli_test(check_no_nip 0 [[nip: none \(T0 = web tension\)]]
            check ${CASES}/newsprint-taper.yaml)
rs_cli_test(check_contact 0 [[nip: contact model \(center-surface winder]]
            check ${SC}/contact.yaml)
rs_cli_test(check_resolved 0 [[^  source: .*models/newsprint\.yaml$]]
            check ${CASES}/newsprint-rider.yaml)

# --- run ---------------------------------------------------------------------------------------
# scripts: tests/cli/<script>.sh REELSIM ...
function(rs_cli_script name script)
  add_test(NAME cli.${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/${script} $<TARGET_FILE:reelsim_cli> ${ARGN}
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(cli.${name} PROPERTIES LABELS cli TIMEOUT 300)
endfunction()

rs_cli_script(run_writes_file run_writes.sh ${SC}/small.yaml)
rs_cli_script(run_bad_input_no_file no_output.sh 2 ${SC}/bad-taper.yaml)
rs_cli_script(run_bad_set_no_file no_output.sh 2 ${SC}/small.yaml --set numerics.rtol=abc)
rs_cli_script(run_bad_model_no_file no_output.sh 2 ${SC}/bad-model.yaml)
# CVODE allowed one step per increment cannot wind a layer onto another (the first layer
# presses on the core and needs no integration): a solver failure, exit 3
rs_cli_script(run_solver_failure_no_file no_output.sh 3 ${SC}/small.yaml --set numerics.max_steps=1)
rs_cli_script(run_interrupted interrupt.sh ${CASES}/newsprint-rider.yaml)
rs_cli_test(run_solver_failure_message 3 [[reelsim: solver failure: .*layers? 2.* of 200]]
            run ${SC}/small.yaml --set numerics.max_steps=1 --set numerics.rtol=1e-5
            -o solver-failure.h5)
rs_cli_test(run_summary 0 [[peak pressure +[0-9.]+ kPa at r = [0-9.]+ mm]]
            run ${SC}/small.yaml -o run-summary.h5)
# a scene with storage stages given to a command that only winds: said, not silently dropped
rs_cli_test(storage_note_compare 0 [[note: .*pet-storage\.yaml has storage stages. `reelsim compare` winds the reel only]]
            compare ${CASES}/pet-storage.yaml ${CASES}/newsprint-rider.yaml -o storage-note.h5
            --set winding.final_radius=0.1)
rs_cli_test(storage_note_sweep 0 [[note: .*pet-storage\.yaml has storage stages. `reelsim sweep` winds the reel only]]
            sweep ${CASES}/pet-storage.yaml --vary winding.tension=100,150 -o storage-note-sweep.h5
            --set winding.final_radius=0.1)

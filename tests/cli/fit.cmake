# reelsim fit stack (docs/calibrate.md)
set(FIT_CSV ${PROJECT_SOURCE_DIR}/cases/data/stack-test.csv)
rs_cli_test(fit_stack_text 0 [[K1 +7[0-9.]+ +7[0-9.]+ \.\. 8[0-9.]+ \(\+- 3\.[0-9] %\)]]
            fit stack ${FIT_CSV} --law pfeiffer)
rs_cli_test(fit_stack_json 0 [[^\{"reelsim":.*"command":"fit stack".*"parameters":\[\{"name":"K1","value":7[0-9.]+,"ci95_low".*"rms_residual":.*"worst":\{"index":]]
            fit stack ${FIT_CSV} --law pfeiffer --json)
rs_cli_test(fit_stack_model 0 [[model +fit-model\.yaml]]
            fit stack ${FIT_CSV} --law hakiel --terms 2 -o fit-model.yaml --base newsprint)
rs_cli_test(fit_stack_cycle1 0 [[K2 +5[0-9.]+]]
            fit stack ${FIT_CSV} --law pfeiffer --cycle 1)
rs_cli_test(fit_stack_too_few 2 [[2 points cannot determine the pfeiffer law's 2 parameters.*at least 3]]
            fit stack ${CMAKE_CURRENT_SOURCE_DIR}/cli/data/stack-two.csv --law pfeiffer)
rs_cli_test(fit_stack_bad_row 2 [[stack-bad\.csv:3: column 2 is not a number]]
            fit stack ${CMAKE_CURRENT_SOURCE_DIR}/cli/data/stack-bad.csv --law linear)
rs_cli_test(fit_stack_bad_law 2 [[--law must be pfeiffer, hakiel, linear or table]]
            fit stack ${FIT_CSV} --law exponential)
# the fitted model loads as a scene's material
rs_cli_test(fit_stack_model_loads 0 [[radial law: hakiel]]
            check ${PROJECT_SOURCE_DIR}/cases/newsprint-taper.yaml --set material=${CMAKE_CURRENT_BINARY_DIR}/fit-model.yaml)
set_tests_properties(cli.fit_stack_model_loads PROPERTIES DEPENDS cli.fit_stack_model)
# reelsim fit roll: synthetic gauge data of small.yaml wound with E_r = 8 MPa (the files'
# headers say how they were made); the fit brackets the true values
set(FIT_SC ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes/small.yaml)
set(FIT_DATA ${CMAKE_CURRENT_SOURCE_DIR}/cli/data)
rs_cli_test(fit_roll_diameter 0 [[material\.radial\.E_r +7\.99[0-9]*e\+06 +7\.9[0-9]*e\+06 \.\. 8\.0[0-9]*e\+06]]
            fit roll ${FIT_SC} --measured ${FIT_DATA}/diameter-length.csv
            --vary material.radial.E_r=2e6:30e6 -o fit-roll-best.yaml)
rs_cli_test(fit_roll_best_loads 0 [[E_r = 7\.99[0-9]*e6 Pa]]
            check fit-roll-best.yaml)
set_tests_properties(cli.fit_roll_best_loads PROPERTIES DEPENDS cli.fit_roll_diameter)
rs_cli_test(fit_roll_pressure_json 0 [[^\{.*"command":"fit roll".*"quantity":"pressure".*"name":"winding\.tension","value":(199|200)\.[0-9]+,"ci95_low":19[0-9.]+,"ci95_high":20[0-9.]+\}.*"rms_residual"]]
            fit roll ${FIT_SC} --measured ${FIT_DATA}/pull-tabs.csv
            --vary material.radial.E_r=2e6:30e6 --vary winding.tension=100:400 --json)
rs_cli_test(fit_roll_too_few 2 [[1 measured points cannot determine 1 keys.*at least 2]]
            fit roll ${FIT_SC} --measured ${FIT_DATA}/one-point.csv --vary winding.tension=100:400)
rs_cli_test(fit_roll_bad_header 2 [[stack-two\.csv:1: the header must name two columns]]
            fit roll ${FIT_SC} --measured ${FIT_DATA}/stack-two.csv --vary winding.tension=100:400)
rs_cli_test(fit_roll_bad_key 2 [[--vary winding\.bogus=100:400: .*unknown key 'bogus']]
            fit roll ${FIT_SC} --measured ${FIT_DATA}/pull-tabs.csv --vary winding.bogus=100:400)
# fit parses its own arguments: its help is reachable all three ways
rs_cli_test(fit_help 0 [[usage: reelsim fit stack TEST\.csv]] fit --help)
rs_cli_test(help_fit 0 [[reelsim fit roll SCENE --measured DATA\.csv]] help fit)
rs_cli_test(fit_stack_help 0 [[usage: reelsim fit stack TEST\.csv]] fit stack --help)
rs_cli_test(fit_roll_help 0 [[reelsim fit roll SCENE --measured DATA\.csv]] fit roll -h)
rs_cli_test(help_lists_fit 0 [[fit stack TEST\.csv \| fit roll SCENE]] --help)

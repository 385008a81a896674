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

# The centrifugal load (docs/scenes.md, "centrifugal"; docs/validation.md, "Speed effects")
set(SPSC ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes)
rs_cli_test(spin_check 0 [[centrifugal load: speed 20 m/s, rho t V\^2 = 22\.4 N/m .*least web tension 350 N/m]]
            check ${SPSC}/spin.yaml)
rs_cli_test(spin_limit 2 [[winding\.speed=100: centrifugal load: at r = 0\.07627 m \(layer 1 of 340\) the web tension 350 N/m is not above rho t V\^2 = 560 N/m]]
            check ${SPSC}/spin.yaml --set winding.speed=100)
rs_cli_test(spin_no_density 2 [[material\.density: required by centrifugal]]
            check ${SPSC}/spin.yaml --set material.density=null)
rs_cli_test(spin_true 0 [[centrifugal load: speed 20 m/s]]
            check ${SPSC}/spin-true.yaml)
rs_cli_test(spin_off 0 [[spin-false\.yaml: ok]]
            check ${SPSC}/spin-false.yaml)
rs_cli_test(spin_midrun 3 [[centrifugal load: at r = 0\.09[0-9]* m \(layer [0-9]+ of 340\) the wound-on tension .* is not above rho t V\^2 = 22\.4 N/m]]
            run ${SPSC}/spin-nip.yaml -o spin-nip-out)

# Numbers with units, plausibility bounds and slip warnings (docs/scenes.md, "Units, bounds
# and plant ranges"; issue 34's five slips each below)
set(USC ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes)
rs_cli_test(units_check 0 [[# units: winding\.tension: 2 pli = 350\.2536704929.* N/m]]
            check ${USC}/plant-units.yaml)
rs_cli_test(units_check_si 0 [[core: rigid \(no core compliance\), radius 50\.1 mm]]
            check ${USC}/plant-units.yaml)
rs_cli_test(units_run 0 [[core pressure]] run ${USC}/plant-units.yaml -o plant-units.h5)
rs_cli_test(units_set 0 [[# units: winding\.speed: 600 m/min = 10 m/s]]
            check ${USC}/small.yaml --set "winding.speed=600 m/min")
rs_cli_test(units_wrong_dimension 2 [[bad-unit\.yaml:10: winding\.speed: '600 kg' is not a speed \(expected a unit of a speed: m/s]]
            check ${USC}/bad-unit.yaml)
rs_cli_test(units_unknown 2 [[unknown unit 'zorks' in '20 zorks' \(expected a length]]
            check ${USC}/small.yaml --set "material.caliper=20 zorks")
# text that is no unit (the scene fuzzer's finding) is refused before UDUNITS' parser
rs_cli_test(units_not_unit_text 2 [[unknown unit '.0\.0e -' in '1.0\.0e -' \(expected a length]]
            check ${USC}/small.yaml --set "material.caliper=1'0.0e -")
rs_cli_test(units_plain_key 2 [[nu_rtheta=0\.3 m: takes a plain number, without a unit]]
            check ${USC}/small.yaml --set "material.nu_rtheta=0.3 m")
# the five slips of issue 34
rs_cli_test(slip_caliper 2 [[material\.caliper=20e-3: 20e-3 m is above the plausible bound 0\.01 m \(1e-9 to 0\.01 m\): did you mean 20e-3 mm\?]]
            run ${USC}/small.yaml --set material.caliper=20e-3 -o slip.h5)
rs_cli_test(slip_core_radius 0 [[warning: .*core\.radius 0\.1524 m: a diameter given as the radius \(core\.diameter: 0\.1524\)\?]]
            check ${USC}/small.yaml --set core.radius=0.1524 --set winding.final_radius=0.2)
rs_cli_test(slip_speed 0 [[warning: .*winding\.speed 600 m/s: did you mean 600 m/min\?]]
            check ${USC}/air.yaml --set winding.speed=600)
rs_cli_test(slip_nip_load 0 [[warning: .*nip\.load 0\.4 N/m: did you mean 0\.4 kN/m\?]]
            check ${PROJECT_SOURCE_DIR}/cases/newsprint-rider.yaml --set nip.load=0.4)
rs_cli_test(slip_tension_start 0 [[warning: .*winding\.tension\.start 0\.12 N/m: did you mean 0\.12 kN/m\?]]
            check ${PROJECT_SOURCE_DIR}/cases/newsprint-taper.yaml --set winding.tension.start=0.12)
rs_cli_script(slip_json units_json.sh ${USC}/small.yaml)
# hard bounds on absurd finite values (issue 36 item 6): exit 2, the bound, no solver coordinates
rs_cli_script(bound_no_solver_coordinates units_bounds.sh ${USC}/small.yaml)
# the effect switches and the core's inside
rs_cli_test(set_centrifugal_true 0 [[centrifugal load: speed 20 m/s]]
            check ${USC}/small.yaml --set centrifugal=true --set winding.speed=20 --set material.density=900)
rs_cli_test(set_air_true 0 [[entrained air: film]]
            check ${USC}/small.yaml --set air=true --set winding.speed=5 --set "air.roughness=0.5 um")
rs_cli_script(set_air_false units_switch.sh ${USC}/air.yaml)
rs_cli_test(core_inner_diameter_wall 0 [[core: rigid \(no core compliance\), radius 50\.1 mm]]
            check ${USC}/small.yaml --set core.radius=null --set "core.inner_diameter=3 in" --set "core.wall=12 mm")
rs_cli_test(core_wall_and_bore 2 [[give one of core\.bore, core\.inner_diameter and core\.wall .*not two]]
            check ${USC}/small.yaml --set core.wall=0.01 --set core.bore=0.03 --set core.modulus=5e9 --set core.poisson=0.3)
rs_cli_script(tutorial tutorial.sh ${PROJECT_SOURCE_DIR}/docs/tutorial.md)

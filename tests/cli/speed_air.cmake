# Entrained air (docs/scenes.md, "air"; docs/validation.md, "Speed effects")
set(AIRSC ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes)
rs_cli_test(air_check 0 [[entrained air: film 24\.[0-9]+ \.\. 32\.[0-9]+ um as wound on .*roughness 0\.5 um: cut-off 1\.5 um does not act]]
            check ${AIRSC}/air.yaml)
rs_cli_test(air_cut 0 [[cut-off 60 um removes every film]]
            check ${AIRSC}/air.yaml --set air.roughness=20e-6)
rs_cli_test(air_no_roughness 2 [[air\.roughness: required by air]]
            check ${AIRSC}/air.yaml --set air.roughness=null)
rs_cli_test(air_material_roughness 0 [[roughness 0\.2 um]]
            check ${AIRSC}/air.yaml --set air.roughness=null --set material.roughness=0.2e-6)
rs_cli_test(air_no_speed 2 [[winding\.speed: required by air]]
            check ${AIRSC}/air.yaml --set winding.speed=null)
rs_cli_test(air_bad_pressure 2 [[air\.pressure=0: must be > 0 Pa, absolute]]
            check ${AIRSC}/air.yaml --set air.pressure=0)
rs_cli_script(air_run air.sh ${AIRSC}/air.yaml)

# Lanes across the width (docs/lanes.md): the scene's errors (exit 2 at file:line:key) and
# the summary's lanes object.
set(SC ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes)
set(LSC ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes/lanes)
rs_cli_test(lanes_edges_not_increasing 2
            [[bad-edges\.yaml:13: lanes\.edges: edges must increase: edge 3 \(0\.3 m\) is not above edge 2]]
            check ${LSC}/bad-edges.yaml)
rs_cli_test(lanes_factor_not_positive 2 [[bad-factor\.yaml:15: lanes\.caliper\[1\]: a factor must be > 0 \(got 0\)]]
            check ${LSC}/bad-factor.yaml)
rs_cli_test(lanes_list_length 2 [[bad-length\.yaml:15: lanes\.caliper: has 2 factors for 3 lanes]]
            check ${LSC}/bad-length.yaml)
rs_cli_test(lanes_too_many 2 [[bad-count\.yaml:14: lanes\.count: must be 1 to 256 lanes \(got 300\)]]
            check ${LSC}/bad-count.yaml)
rs_cli_test(lanes_tension_factor 2 [[bad-tension\.yaml:15: lanes\.tension_profile\[1\]: a factor must be > 0]]
            check ${LSC}/bad-tension.yaml)
rs_cli_test(lanes_roller_needs_nip 2 [[bad-roller\.yaml:15: lanes\.nip: roller shares the nip's load: the scene has no nip]]
            check ${LSC}/bad-roller.yaml)
rs_cli_test(lanes_per_step 2 [[--set numerics\.layers_per_step=4: must be 1 with lanes]]
            check ${LSC}/band.yaml --set numerics.layers_per_step=4)
rs_cli_test(lanes_json 0 [["lanes":{"count":3,"ridge_height":[0-9.e-]+,"ridge_x":0\.45,"hardest":{"x":0\.45]]
            run --json -o lanes-band.h5 ${LSC}/band.yaml)
rs_cli_test(lanes_summary 0 [[hardest lane +x = 0\.45 m]]
            run -o lanes-band-text.h5 ${LSC}/band.yaml)
rs_cli_test(lanes_none_json 0 [["lanes":null]]
            run --json -o lanes-none.h5 ${SC}/small.yaml)
rs_cli_script(lanes_plot lanes_plot.sh ${LSC}/band.yaml ${SC}/small.yaml)
# the lanes' figures of compare, sweep and optimize against the run's own summary
foreach(cmd compare sweep optimize)
  rs_cli_script(lanes_figures_${cmd} lanes_figures.sh ${cmd} ${LSC}/band.yaml ${SC}/small.yaml)
endforeach()

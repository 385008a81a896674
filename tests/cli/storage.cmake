# Storage after the winder (docs/storage.md): the stages in the file and the summary,
# the keys' checks.
set(SC ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes)
rs_cli_script(storage_h5dump storage_h5dump.sh ${SC}/storage-small.yaml)
rs_cli_test(storage_summary 0 [[core pressure +worst at stage [0-3] \(]]
            run ${SC}/storage-small.yaml -o storage-summary.h5)
rs_cli_test(storage_check_lists 0 [[storage: 3 stages, 36\.5 h, wound at 23 C and 50 % RH]]
            check ${SC}/storage-small.yaml)
rs_cli_test(storage_no_thermal 2
            [[bad-storage-thermal\.yaml:11: storage\[1\]\.temperature: changes the temperature \(23 -> 40 C\) but the material has no material\.thermal]]
            check ${SC}/bad-storage-thermal.yaml)
rs_cli_test(storage_prony_sum 2
            [[bad-prony-sum\.yaml:[0-9]+: material\.viscoelastic\.E_theta: the fractions must sum to less than 1]]
            check ${SC}/bad-prony-sum.yaml)
rs_cli_test(storage_prony_lengths 2
            [[bad-prony-lengths\.yaml:[0-9]+: material\.viscoelastic\.radial: must have one entry per relaxation time]]
            check ${SC}/bad-prony-lengths.yaml)
rs_cli_test(storage_humidity_range 2 [=[winding\.humidity=120: must lie in \[0, 100\]]=]
            check ${SC}/storage-small.yaml --set winding.humidity=120)
rs_cli_script(storage_plot storage_plot.sh ${SC}/storage-small.yaml)
rs_cli_test(storage_no_hygroscopic 2
            [[storage\[0\]\.humidity=80: changes the humidity \(50 -> 80 % RH\) but the material has no material\.hygroscopic]]
            check ${SC}/bad-storage-thermal.yaml --set storage[0].humidity=80)
rs_cli_test(storage_negative_hours 2 [[storage\[0\]\.hours=-1: must be >= 0 h]]
            check ${SC}/storage-small.yaml --set storage[0].hours=-1)
rs_cli_test(storage_tau_positive 2 [[material\.viscoelastic\.tau\[1\]=0: must be > 0 h]]
            check ${SC}/bad-prony-sum.yaml --set material.viscoelastic.E_theta[0]=0.1
            --set material.viscoelastic.tau[1]=0)
rs_cli_test(storage_layers_part 0 [[note: stage 1 leaves [0-9]+ interfaces in radial tension]]
            run ${SC}/storage-loose.yaml -o storage-loose.h5)

# The two-drum winder case (cases/newsprint-two-drum.yaml; docs/nip.md, "Two-drum winders").
# By hand: at the core (R = 0.0762 m) only the rider's 1500 N/m presses the roll on the drums,
# sin theta = 0.525/0.5762, each drum 1500/(2 cos theta) = 1819.98 N/m; at R = 0.5 m the
# weight 640 g pi (0.25 - 0.0762^2) = 4814.87 N/m and the rider's 300 N/m, cos theta = 0.851,
# each drum 3004.85 N/m; NIT = 0.19 (2 x 1819.98 + 1500) = 976.59 N/m, at the end
# 2 x min(0.19 x 3004.85, 380) + 0.19 x 300 = 817 N/m (uncapped 1198.84 N/m).
set(TDC ${PROJECT_SOURCE_DIR}/cases/newsprint-two-drum.yaml)
rs_cli_test(two_drum_check_loads 0 [[nip\[0\], rear drum: friction \(NIT = 0\.19 N\). load from the statics, 1819\.98 N/m at the core -> 3004\.85 N/m at the final radius]]
            check ${TDC})
rs_cli_test(two_drum_check_nit 0 [[NIT 976\.592 N/m at the core -> 817 N/m at the final radius \(sum of mu N, the upper bound: 976\.592 -> 1198\.84 N/m\)]]
            check ${TDC})
rs_cli_test(two_drum_check_cap 0 [[nip saturation: each nip adds at most 380 N/m]]
            check ${TDC})
rs_cli_test(two_drum_run 0 [[wound-on tension +1092\.1 \.\. 1326\.6 N/m]]
            run ${TDC} -o two-drum.h5)
rs_cli_test(two_drum_run_uncapped 0 [[wound-on tension +1092\.1 \.\. 1548\.6 N/m]]
            run ${TDC} -o two-drum-uncapped.h5 --set material.nit_saturation=null)
rs_cli_test(two_drum_falls_between 2 [[winder\.drum_distance=1\.3: winder: a roll of radius 0\.0762 m falls between drums]]
            check ${TDC} --set winder.drum_distance=1.3)
# reelsim nip solves one nip: a list is refused, naming why
rs_cli_test(two_drum_nip_refused 2 [[reelsim nip' solves one nip. this scene lists several]]
            nip ${TDC} --radius 0.3)

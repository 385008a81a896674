# Whole-reel reports: stress history, CSV export, defect-risk indicators, progress bar.
set(SC ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes)
set(CASES ${PROJECT_SOURCE_DIR}/cases)

rs_cli_script(history_h5dump history_h5dump.sh ${SC}/small.yaml)
rs_cli_test(history_too_large 2
            [[small\.yaml: output\.history_every = 1 would store 49500 stages of 49500 layers.*use output\.history_every >= 19]]
            run ${SC}/small.yaml --set winding.final_radius=5 --set output.history_every=1 -o history-too-large.h5)
rs_cli_script(run_history_too_large_no_file no_output.sh 2 ${SC}/small.yaml
              --set winding.final_radius=5 --set output.history_every=1)

rs_cli_script(csv_writes csv_writes.sh ${SC}/small.yaml)
# --csv DIR is made as needed (mkdir -p); a path that is a file, or below one, is refused
# before winding, with nothing written
rs_cli_script(csv_makes_dir csv_writes.sh ${SC}/small.yaml made/csv)
rs_cli_test(csv_not_dir 2 [[reelsim: --csv '.*small\.yaml' is not a directory]]
            run ${SC}/small.yaml -o csv-not-dir.h5 --csv ${SC}/small.yaml)
rs_cli_script(run_csv_not_dir_no_file no_output.sh 2 ${SC}/small.yaml --csv ${SC}/small.yaml)
rs_cli_script(run_csv_below_file_no_file no_output.sh 2 ${SC}/small.yaml --csv ${SC}/small.yaml/csv)
rs_cli_test(csv_check_refused 2 [[reelsim: check: --csv only applies to run]]
            check ${SC}/small.yaml --csv .)

# Hoop compression is information, the starring rule weighs it (docs/defects.md): the
# falling-taper scene compresses its inner layers (-3.5 MPa); the compressed zone, bonded
# by friction, is far from buckling as a packet on the core, so no WARNING line at all.
rs_cli_script(falling_taper_hoop_info summary_lines.sh
              [[^  hoop stress +compression \(sigma_theta < 0\) in [0-9]+ layers at r = 76\.3 \.\. [0-9.]+ mm. least -3\.[0-9]+ MPa at r = 76\.[0-9] mm$]]
              [[^  starring +packet margin N_cr/N = [0-9]+ \(N [0-9.]+ kN/m against [0-9.]+ kN/m. zone r = 76\.2 \.\. 92\.1 mm \(0\.0 \.\. 0\.6 in from the core\), [0-9]+ layers bonded, mode [0-9]+\): ok$]]
              -- run ${CASES}/newsprint-falling-taper.yaml -o falling-taper.h5)
# A core that gives way (E_c = 0.5 MPa) under the same recipe: -49.7 MPa at the core,
# over a hoop strength of 20 MPa, a WARNING decided by the strength.
rs_cli_test(soft_core_starring_strength 0
            [[WARNING: starring risk in [0-9]+ layers? at r = 76\.3 \.\. [0-9.]+ mm: hoop_strength margin 0\.[0-9]+ \(least sigma_theta -49\.[0-9]+ MPa at r = 76\.3 mm\)]]
            run ${CASES}/newsprint-falling-taper.yaml -o soft-core-buckling.h5
            --set core.stiffness=5e5 --set material.hoop_strength=2e7)
# The same zone at E_c = 50 MPa (-15.9 MPa) when a speed change's torque uses up the
# friction near the core: its layers slip and the packet buckles (mode 36), a WARNING.
rs_cli_test(slipping_zone_starring 0
            [[WARNING: starring risk in 288 layers at r = 76\.3 \.\. 96\.4 mm: packet margin N_cr/N = 0\.2[0-9] .*288 layers slipping, mode [0-9]+\)]]
            run ${CASES}/newsprint-falling-taper.yaml -o slipping-zone.h5
            --set core.stiffness=5e7 --set material.friction_layer=0.3 --set winding.accel_torque=20000)
# Bonded, the same zone holds: margin 63, mode 2.
rs_cli_test(bonded_zone_no_starring 0
            [[  starring +packet margin N_cr/N = [0-9]+ .*288 layers bonded, mode 2\): ok]]
            run ${CASES}/newsprint-falling-taper.yaml -o bonded-zone.h5 --set core.stiffness=5e7)
# The rider case with a 2000 N m/m speed change: the torque each interface carries
# (T R + I_out alpha) against mu P 2 pi r^2 leaves 6.3 near the core: no WARNING.
rs_cli_test(rider_accel_no_slip 0
            [[  interlayer slip +friction torque capacity >= 6\.3[0-9] x the torque carried \(217[0-9.]+ N m/m at r = 79\.9 mm. center drive, T R 175 N m/m, inertia torque 2000 N m/m. from 1 wrap below the surface\): ok]]
            run ${CASES}/newsprint-rider.yaml -o rider-accel.h5 --set winding.accel_torque=2000
            --set material.friction_layer=0.3 --set numerics.rtol=1e-3)
rs_cli_script(falling_taper_defects_file defects_file.sh ${CASES}/newsprint-falling-taper.yaml)
rs_cli_test(defects_not_assessed 0 [[interlayer slip +not assessed \(no material\.friction_layer\)]]
            run ${SC}/small.yaml -o defects-not-assessed.h5)
rs_cli_test(defects_core_rating_risk 0 [[WARNING: core pressure [0-9.]+ kPa exceeds core\.rating 100\.00 kPa]]
            run ${SC}/small.yaml -o defects-core.h5 --set core.rating=1e5)
rs_cli_test(defects_slip_risk 0 [[WARNING: interlayer slip \(cinching\) risk at [0-9]+ interfaces]]
            run ${SC}/small.yaml -o defects-slip.h5 --set material.friction_layer=0.2
            --set winding.accel_torque=2000)
rs_cli_test(check_defect_checks 0 [[interlayer slip check: winding\.accel_torque 50 N m/m, web-on-web friction 0\.3]]
            check ${SC}/small.yaml --set material.friction_layer=0.3 --set winding.accel_torque=50)
rs_cli_test(bad_pressure_limit 2 [[--set material\.pressure_limit=0: must be > 0 Pa]]
            check ${SC}/small.yaml --set material.pressure_limit=0)
rs_cli_test(bad_accel_without_friction 2 [[--set winding\.accel_torque=50: the interlayer slip check needs material\.friction_layer]]
            check ${SC}/small.yaml --set winding.accel_torque=50)

rs_cli_script(progress_tty progress_tty.sh ${CASES}/newsprint-falling-taper.yaml)

# A steep rising taper compresses the inner layers: reported, no starring WARNING.
rs_cli_script(rising_taper_hoop_info summary_lines.sh
              [[^  hoop stress +compression \(sigma_theta < 0\) in [0-9]+ layers at r = [0-9.]+ \.\. [0-9.]+ mm. least -[0-9.]+ MPa at r = [0-9.]+ mm$]]
              [[^  starring +packet margin .*: ok$]]
              -- run ${SC}/rising-taper.yaml -o rising-taper.h5)
# The TopWeb example (cases/pet-topweb.yaml): hoop compression through most of the roll,
# no WARNING (TopWeb: "no wrinkle or tin-canning warning"), the 636 mm roll.
rs_cli_script(topweb_no_warning summary_lines.sh
              [[^  final radius +318\.0 mm$]]
              [[^  hoop stress +compression \(sigma_theta < 0\) in [0-9]+ layers]]
              [[^  starring +packet margin .*: ok$]]
              -- run ${CASES}/pet-topweb.yaml -o pet-topweb.h5)

# reelsim nip: one contact nip at a given roll radius (docs/nip.md)
set(NSC ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes)
rs_cli_test(nip_text 0 [[wound-on tension T0 434\.0[0-9]* N/m \(NIT = 84\.0]]
            nip ${NSC}/contact.yaml --radius 0.3)
rs_cli_test(nip_json 0 [[^\{"radius":0\.(3|29999).*"a":.*"load":17(50|49\.9999).*"T0":.*"xi2":.*"delta0":.*"eps0":.*"iterations":.*"condition_number":.*"x":\[.*"pressure":\[.*"x_shear":\[.*"shear_upper":\[.*"shear_lower":\[.*"slip_upper":\[(true|false).*"slip_lower":\[.*\}$]]
            nip ${NSC}/contact.yaml --radius 0.3 --json)
rs_cli_test(nip_bad_load 2 [[nip\.load = 1e\+08 N/m needs a contact half-width beyond]]
            nip ${NSC}/contact.yaml --radius 0.3 --set nip.load=1e8) # 1e8: nip.load's hard bound
rs_cli_test(nip_bad_friction 2 [[nip\.friction\.roll.*must be >= 0]]
            nip ${NSC}/contact.yaml --radius 0.3 --set nip.friction.roll=-0.1)
rs_cli_test(nip_bad_drum_core 2 [[nip\.drum\.radius: must be > nip\.drum\.core_radius]]
            nip ${NSC}/contact.yaml --radius 0.3 --set nip.drum.core_radius=0.4)
# refused when the scene is read (docs/scenes.md, "nip"): the drum cannot carry the web
rs_cli_test(nip_surface_friction 2 [[nip\.friction\.drum: the drum cannot carry the web by friction from roll radius r = 0\.0762 m \(layer 1 of [0-9]+\) on: nip\.friction\.drum x nip\.load = 0\.35 x 500 = 175 N/m is not above winding\.tension = 350 N/m]]
            nip ${NSC}/nip-surface.yaml --radius 0.15 --set nip.load=500)
rs_cli_test(nip_needs_radius 2 [[need SCENE and --radius]]
            nip ${NSC}/contact.yaml)
rs_cli_test(nip_center 0 [[NIT = 307\.5[0-9]* N/m, mu_roll P = 332\.5 N/m]]
            nip ${NSC}/nip-center.yaml --radius 0.15)
# the rider cases the first version could not solve (docs/nip.md, "The rider"): the
# brief's mu_roll = 1.0 at low load (after the wound-on fix the iteration finds it), and a
# slippery rider that needs the LCP (Lemke) fallback
rs_cli_test(nip_rider_high_mu_roll 0 [[NIT = 245\.9[0-9]* N/m, mu_roll P = 500 N/m]]
            nip ${NSC}/nip-center.yaml --radius 0.15 --set nip.friction.roll=1.0 --set nip.load=500)
rs_cli_test(nip_rider_slippery 0 [[NIT = 183\.3[0-9]* N/m, mu_roll P = 190 N/m]]
            nip ${NSC}/nip-center.yaml --radius 0.15 --set nip.friction.drum=0.1 --set nip.load=1000)

# Speed effects: entrained air (docs/validation.md, "Speed effects")
rs_test(test_air validation SOURCES validation/test_air.c
        CASES film_law roughness_cutoff compression_identity roll_series all_cut_is_no_air reel_identities
              topweb refused)
target_compile_definitions(test_air PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")
# very high speed (with the centrifugal load), a very smooth film, a heavy and a light nip,
# a web tension of 0
rs_test(test_air_hard hard SOURCES validation/test_air.c CASES hard_fast hard_smooth hard_nip hard_slack)
target_compile_definitions(test_air_hard PRIVATE RS_ROOT_DIR="${PROJECT_SOURCE_DIR}")
# the nodes at their real radii against the exact ring statics of the same build-up
rs_test(test_air_radius validation SOURCES validation/test_air_radius.c
        CASES film_as_web_rigid thin_film_elastic)

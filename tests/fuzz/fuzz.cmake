# Scene-loader and HDF5-reader fuzzing (docs/robustness.md).
# Always: the kept inputs (seed corpus and crash reproducers) replayed through the same
# target function in the ordinary build, label unit (and valgrind).
rs_test(fuzz_replay unit SOURCES fuzz/replay.c fuzz/fuzz_scene.c CASES corpus crashes)
target_compile_definitions(fuzz_replay PRIVATE RS_FUZZ_DIR="${CMAKE_CURRENT_SOURCE_DIR}/fuzz")
# The HDF5 reader's target (fuzz_h5.c) over its seed files (h5corpus: small valid files).
rs_test(fuzz_h5_replay unit SOURCES fuzz/replay.c fuzz/fuzz_h5.c CASES h5corpus)
target_compile_definitions(fuzz_h5_replay PRIVATE RS_FUZZ_DIR="${CMAKE_CURRENT_SOURCE_DIR}/fuzz")
target_include_directories(fuzz_h5_replay PRIVATE ${PROJECT_SOURCE_DIR}/src)

# -DREELSIM_FUZZ=ON (clang): the libFuzzer binary; scripts/fuzz.sh runs it.
if(REELSIM_FUZZ)
  add_executable(fuzz_scene fuzz/fuzz_scene.c)
  target_include_directories(fuzz_scene PRIVATE ${PROJECT_SOURCE_DIR}/src) # scene/scene_type.h
  target_link_libraries(fuzz_scene PRIVATE reelsim_lib)
  target_link_options(fuzz_scene PRIVATE -fsanitize=fuzzer)
  add_executable(fuzz_h5 fuzz/fuzz_h5.c)
  target_include_directories(fuzz_h5 PRIVATE ${PROJECT_SOURCE_DIR}/src) # output/h5_read_check.h
  target_link_libraries(fuzz_h5 PRIVATE reelsim_lib)
  target_link_options(fuzz_h5 PRIVATE -fsanitize=fuzzer)
endif()

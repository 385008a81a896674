# Hostile YAML (docs/scenes.md, "Limits"): refused while it is read, exit 2, naming the
# limit. The inputs are the fuzz corpus's; unbounded, the billion laughs would expand to
# 4.3e7 values (42 s and 9.9 GB before this bound) and the deep ones take libyaml's
# document loader seconds to minutes, so these pass only when the bounds work.
set(HOSTILE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/corpus)
rs_cli_test(hostile_billion_laughs 2
  [[hostile-billion-laughs\.yaml:5: too many alias expansions \(limit 10000 values copied from anchors\)]]
  check ${HOSTILE}/hostile-billion-laughs.yaml)
rs_cli_test(hostile_model_file 2
  [[fuzz/corpus/hostile-billion-laughs\.yaml:5: too many alias expansions]]
  check ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes/hostile-model.yaml)
rs_cli_test(hostile_deep_flow 2
  [[hostile-deep-flow\.yaml:1: nesting deeper than 64 levels \(the limit for scene files\)]]
  check ${HOSTILE}/hostile-deep-flow.yaml)
rs_cli_test(hostile_deep_block 2 [[hostile-deep-block\.yaml:2: nesting deeper than 64 levels]]
  run ${HOSTILE}/hostile-deep-block.yaml -o hostile.h5)
rs_cli_test(hostile_alias_cycle 2 [[hostile-alias-cycle\.yaml:1: x\[1\]: alias \*a names no complete anchor]]
  check ${HOSTILE}/hostile-alias-cycle.yaml)
rs_cli_test(hostile_wide_mapping 2 [[hostile-wide-mapping\.yaml:258: x: more than 256 keys in one mapping]]
  check ${HOSTILE}/hostile-wide-mapping.yaml)
rs_cli_test(hostile_many_values 2 [[hostile-many-values\.yaml:1: more than 20000 values in one file]]
  check ${HOSTILE}/hostile-many-values.yaml)
# an endless file: read only up to the size limit
rs_cli_test(hostile_endless_file 2 [[/dev/zero: larger than 1048576 bytes \(the limit for scene files\)]]
  check /dev/zero)

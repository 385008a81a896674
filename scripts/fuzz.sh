#!/usr/bin/env bash
# Fuzzes the scene loader and the HDF5 reader with libFuzzer for a bounded time
# (docs/robustness.md).
#   bash scripts/fuzz.sh [SECONDS]      (default 60; or RS_FUZZ_SECONDS)
# The time is split: the scene loader gets SECONDS - SECONDS/2, the HDF5 reader SECONDS/2
# (RS_FUZZ_H5_SECONDS overrides the reader's share; 0 skips it), so the total stays SECONDS.
# Builds build-fuzz/ with clang (-DREELSIM_FUZZ=ON: libFuzzer + ASan + UBSan). For each
# target it copies the seed corpus (tests/fuzz/corpus/ for scenes, tests/fuzz/h5corpus/ for
# HDF5 files) and the kept reproducers (tests/fuzz/crashes/, tests/fuzz/h5crashes/) into a
# scratch corpus (the repository's are never modified), and runs the target
# (tests/fuzz/fuzz_scene.c, tests/fuzz/fuzz_h5.c) from an empty directory. A finding stops
# it with status 1 and the input saved as build-fuzz/findings/crash-*: fix the bug, then
# keep the input beside the seeds' folder (crashes/ or h5crashes/; the unit tests
# fuzz_replay.* and fuzz_h5_replay.* replay the kept inputs in every build).
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"
seconds="${1:-${RS_FUZZ_SECONDS:-60}}"
h5_seconds="${RS_FUZZ_H5_SECONDS:-$((seconds / 2))}"
scene_seconds=$((seconds - h5_seconds))
[ "$scene_seconds" -ge 1 ] || scene_seconds=1
command -v clang >/dev/null || { echo "fuzz: clang is not installed (scripts/setup.sh installs it)" >&2; exit 1; }

CC=clang cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DREELSIM_FUZZ=ON \
  -DREELSIM_BENCH=OFF -DREELSIM_DEVELOPER=ON >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target fuzz_scene fuzz_h5 >/dev/null

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p build-fuzz/findings

# fuzz_one TARGET WHAT SECONDS SEEDS CRASHES MAX_LEN [libFuzzer options...]
fuzz_one() {
  local target="$1" what="$2" secs="$3" seeds="$4" crashes="$5" max_len="$6"
  shift 6
  mkdir -p "$work/$target/corpus" "$work/$target/run"
  cp "tests/fuzz/$seeds"/* "$work/$target/corpus/"
  [ -d "tests/fuzz/$crashes" ] &&
    find "tests/fuzz/$crashes" -type f ! -name '.*' -exec cp {} "$work/$target/corpus/" \;
  echo "== fuzzing the $what for ${secs} s (libFuzzer) =="
  # -timeout: an input that takes 10 s is a hang (nothing may loop);
  # -rss_limit_mb: one that needs 2 GB is a finding too.
  local status=0
  (cd "$work/$target/run" && "$root/build-fuzz/tests/$target" -max_total_time="$secs" \
     -timeout=10 -rss_limit_mb=2048 -max_len="$max_len" -print_final_stats=1 "$@" \
     -artifact_prefix="$root/build-fuzz/findings/" \
     "$work/$target/corpus" > "$work/$target/log" 2>&1) || status=$?
  grep -E '^(#[0-9]+ +DONE|Done [0-9]+ runs|stat::number_of_executed_units|stat::new_units_added)' \
    "$work/$target/log" || true
  if [ "$status" -ne 0 ]; then
    tail -n 60 "$work/$target/log"
    echo "fuzz: $what FAILED (status $status); reproducer(s) in build-fuzz/findings/:" >&2
    ls -1 build-fuzz/findings >&2
    exit 1
  fi
}

LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan-udunits.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}" \
  fuzz_one fuzz_scene "scene loader" "$scene_seconds" corpus crashes 4096 \
  -dict="$root/tests/fuzz/scene.dict"
# HDF5 files: the seeds are 16-33 kB; an input may grow a little beyond the largest
if [ "$h5_seconds" -gt 0 ]; then
  LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan-hdf5.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}" \
    fuzz_one fuzz_h5 "HDF5 reader" "$h5_seconds" h5corpus h5crashes 65536
fi
echo "fuzz: no finding in ${scene_seconds} s (scene loader) + ${h5_seconds} s (HDF5 reader)"

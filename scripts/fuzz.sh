#!/usr/bin/env bash
# Fuzzes the scene loader with libFuzzer for a bounded time (docs/robustness.md).
#   bash scripts/fuzz.sh [SECONDS]      (default 60; or RS_FUZZ_SECONDS)
# Builds build-fuzz/ with clang (-DREELSIM_FUZZ=ON: libFuzzer + ASan + UBSan), copies the
# seed corpus tests/fuzz/corpus/ and the kept reproducers tests/fuzz/crashes/ into a
# scratch corpus (the repository's are never modified), and runs the target
# tests/fuzz/fuzz_scene.c from an empty directory. A finding stops it with status 1 and
# the input saved as build-fuzz/findings/crash-*: fix the bug, then keep the input as
# tests/fuzz/crashes/<name> (the unit test fuzz_replay.crashes replays it in every build).
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"
seconds="${1:-${RS_FUZZ_SECONDS:-60}}"
command -v clang >/dev/null || { echo "fuzz: clang is not installed (scripts/setup.sh installs it)" >&2; exit 1; }

CC=clang cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DREELSIM_FUZZ=ON \
  -DREELSIM_BENCH=OFF -DREELSIM_DEVELOPER=ON >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target fuzz_scene >/dev/null

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/corpus" "$work/run" build-fuzz/findings
cp tests/fuzz/corpus/* "$work/corpus/"
find tests/fuzz/crashes -type f ! -name '.*' -exec cp {} "$work/corpus/" \;

echo "== fuzzing the scene loader for ${seconds} s (libFuzzer) =="
# -timeout: an input that takes 10 s is a hang (the loader must never loop);
# -rss_limit_mb: one that needs 2 GB is a finding too.
status=0
(cd "$work/run" && "$root/build-fuzz/tests/fuzz_scene" -max_total_time="$seconds" \
   -timeout=10 -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 \
   -dict="$root/tests/fuzz/scene.dict" -artifact_prefix="$root/build-fuzz/findings/" \
   "$work/corpus" > "$work/log" 2>&1) || status=$?
grep -E '^(#[0-9]+ +DONE|Done [0-9]+ runs|stat::number_of_executed_units|stat::new_units_added)' \
  "$work/log" || true
if [ "$status" -ne 0 ]; then
  tail -n 60 "$work/log"
  echo "fuzz: FAILED (status $status); reproducer(s) in build-fuzz/findings/:" >&2
  ls -1 build-fuzz/findings >&2
  exit 1
fi
echo "fuzz: no finding in ${seconds} s"

#!/usr/bin/env bash
# keep_partial.sh REELSIM SCENE ARGS...: with --keep-partial a failing run (ARGS make it
# fail) still exits 3, names the layer it reached, and writes exactly the output file with
# complete = 0 and the layers the message names. When ARGS are given, the run without them
# succeeds and marks complete = 1.
set -u
bin="$1"; scene="$2"; shift 2
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
out="$("$bin" run "$scene" -o "$tmp/out.h5" --keep-partial "$@" 2>&1)"; got=$?
printf '%s\n' "$out"
[ "$got" -eq 3 ] || fail "exit status $got, expected 3"
k="$(printf '%s\n' "$out" | sed -nE 's/^reelsim:   ([0-9]+) of [0-9]+ layers were wound; partial result written to .* \(complete = 0\)$/\1/p')"
[ -n "$k" ] || fail "no 'k of N layers were wound; partial result written' message"
h5dump -a complete "$tmp/out.h5" | grep -Eq '\(0\): 0$' || fail "attribute complete is not 0"
h5dump -a layers "$tmp/out.h5" | grep -Eq "\(0\): $k\$" || fail "attribute layers is not $k"
h5dump -d /final/sigma_r -H "$tmp/out.h5" | grep -Eq "DATASPACE +SIMPLE \{ \( $k \)" ||
  fail "/final/sigma_r does not hold $k layers"
[ "$(ls -A "$tmp")" = "out.h5" ] || { ls -la "$tmp"; fail "stray files"; }
if [ "$#" -gt 0 ]; then
  "$bin" run "$scene" -o "$tmp/ok.h5" --keep-partial --quiet || fail "the plain run failed"
  h5dump -a complete "$tmp/ok.h5" | grep -Eq '\(0\): 1$' || fail "complete is not 1 on success"
fi
echo PASS

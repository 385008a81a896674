#!/usr/bin/env bash
# run_writes.sh REELSIM SCENE: `run` exits 0, prints the summary and writes the output
# file: to -o FILE, and by default to <scene name>.h5 in the current directory.
set -u
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

out="$("$bin" run "$scene" -o "$tmp/explicit.h5" 2>&1)"; got=$?
printf '%s\n' "$out"
[ "$got" -eq 0 ] || fail "exit status $got, expected 0"
[ -s "$tmp/explicit.h5" ] || fail "no output file $tmp/explicit.h5"
for want in 'final radius +70\.0 mm' 'layers +200' 'core pressure +[0-9.]+ kPa' \
            'peak pressure .* at r = ' 'min hoop stress .* at r = ' 'wound-on tension +200\.0 \.\. 200\.0 N/m' \
            'wall time' "output +$tmp/explicit\.h5"; do
  printf '%s\n' "$out" | grep -Eq -- "$want" || fail "summary lacks /$want/"
done
if printf '%s\n' "$out" | grep -Eiq '(^|[^a-z])(nan|-?inf)([^a-z]|$)'; then fail "NaN/Inf printed"; fi
# nothing else left beside it (the temporary name was renamed away)
[ "$(ls -A "$tmp" | wc -l)" -eq 1 ] || { ls -la "$tmp"; fail "stray files beside the output"; }

# default output name: <scene stem>.h5 in the working directory, --quiet prints nothing
grep -v '^output:' "$scene" > "$tmp/plain-roll.yaml"
(cd "$tmp" && "$bin" run plain-roll.yaml --quiet > quiet.log 2>&1) || fail "default-name run failed"
[ -s "$tmp/plain-roll.h5" ] || fail "no default output plain-roll.h5"
[ ! -s "$tmp/quiet.log" ] || { cat "$tmp/quiet.log"; fail "--quiet printed something"; }
echo PASS

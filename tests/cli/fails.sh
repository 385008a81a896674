#!/usr/bin/env bash
# fails.sh REELSIM STATUS REGEX [REGEX ...] -- ARGS...: `reelsim run ARGS -o DIR/out.h5`,
# in an empty directory DIR, exits with STATUS, its messages match every REGEX (grep -E,
# each somewhere in stdout+stderr), it prints no NaN or Inf, and DIR stays empty.
set -u
bin="$1"; want="$2"; shift 2
regexes=()
while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do regexes+=("$1"); shift; done
shift
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
out="$(cd "$tmp" && "$bin" run "$@" -o "$tmp/out.h5" 2>&1)"; got=$?
printf '%s\n' "$out"
echo "exit status: $got (expected $want)"
[ "$got" -eq "$want" ] || { echo "FAIL: wrong exit status"; exit 1; }
for r in "${regexes[@]}"; do
  printf '%s\n' "$out" | grep -Eq -- "$r" || { echo "FAIL: output does not match /$r/"; exit 1; }
done
if printf '%s\n' "$out" | grep -Eiq -- '(^|[^a-z])(nan|-?inf)([^a-z]|$)'; then
  echo "FAIL: output contains NaN or Inf"; exit 1
fi
if [ -n "$(ls -A "$tmp")" ]; then ls -la "$tmp"; echo "FAIL: files were written"; exit 1; fi
echo PASS

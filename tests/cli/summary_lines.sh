#!/usr/bin/env bash
# summary_lines.sh REELSIM REGEX... -- ARGS...: runs `REELSIM ARGS...`, passes when it
# exits 0, every REGEX (extended, grep -E) matches a line of its output, and no line holds
# a WARNING (the summary's information lines must stay information).
set -u
bin="$1"; shift
regexes=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do regexes+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
out="$("$bin" "$@" 2>&1)"; got=$?
printf '%s\n' "$out"
[ "$got" -eq 0 ] || { echo "FAIL: exit status $got"; exit 1; }
for re in "${regexes[@]}"; do
  printf '%s\n' "$out" | grep -Eq -- "$re" || { echo "FAIL: no line matches /$re/"; exit 1; }
done
if printf '%s\n' "$out" | grep -q 'WARNING'; then echo "FAIL: a WARNING line"; exit 1; fi
echo PASS

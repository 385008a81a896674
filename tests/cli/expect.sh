#!/usr/bin/env bash
# expect.sh STATUS REGEX -- COMMAND...
# Runs COMMAND, passes when it exits with STATUS and its stdout+stderr match REGEX
# (extended regex, grep -E). Prints what it saw, so a failure is readable in ctest logs.
set -u
want="$1"; regex="$2"; shift 2
[ "$1" = "--" ] && shift
out="$("$@" 2>&1)"; got=$?
printf '%s\n' "$out"
echo "exit status: $got (expected $want)"
if [ "$got" -ne "$want" ]; then echo "FAIL: wrong exit status"; exit 1; fi
if ! printf '%s\n' "$out" | grep -Eq -- "$regex"; then echo "FAIL: output does not match /$regex/"; exit 1; fi
if printf '%s\n' "$out" | grep -Eiq -- '(^|[^a-z])(nan|-?inf)([^a-z]|$)'; then
  echo "FAIL: output contains NaN or Inf"; exit 1
fi
echo "PASS"

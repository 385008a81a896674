#!/usr/bin/env bash
# no_output.sh REELSIM STATUS SCENE [ARGS...]: a run that fails (bad input: 2, solver: 3)
# exits with STATUS and leaves nothing on disk, not even a temporary file.
set -u
bin="$1"; want="$2"; scene="$3"; shift 3
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
out="$(cd "$tmp" && "$bin" run "$scene" -o "$tmp/out.h5" "$@" 2>&1)"; got=$?
printf '%s\n' "$out"
echo "exit status: $got (expected $want)"
[ "$got" -eq "$want" ] || { echo "FAIL: wrong exit status"; exit 1; }
if [ -n "$(ls -A "$tmp")" ]; then ls -la "$tmp"; echo "FAIL: files were written"; exit 1; fi
echo PASS

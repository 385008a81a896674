#!/usr/bin/env bash
# interrupt.sh REELSIM SCENE: Ctrl-C (SIGINT) during `run` stops it after the current
# step, writes no file, says where it stopped, and exits 130.
set -u
set -m   # job control: the background run gets SIGINT like a foreground one would
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
# a reel long enough (tens of seconds) that the signal lands mid-run
"$bin" run "$scene" --set winding.final_radius=1.5 -o "$tmp/out.h5" > "$tmp/log" 2>&1 &
pid=$!
sleep 1
kill -INT "$pid"
wait "$pid"; got=$?
cat "$tmp/log"
echo "exit status: $got (expected 130)"
[ "$got" -eq 130 ] || { echo "FAIL: wrong exit status"; exit 1; }
grep -Eq 'reelsim: interrupted at layer [0-9]+ of [0-9]+ \(no output written\)' "$tmp/log" ||
  { echo "FAIL: no 'interrupted at layer k of N' message"; exit 1; }
[ ! -e "$tmp/out.h5" ] || { echo "FAIL: an output file was written"; exit 1; }
[ "$(ls -A "$tmp")" = "log" ] || { ls -la "$tmp"; echo "FAIL: stray files"; exit 1; }
echo PASS

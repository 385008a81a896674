#!/usr/bin/env bash
# interrupt_nip.sh REELSIM SCENE: Ctrl-C during a contact nip solve at the largest sizes
# the scene keys allow (nip.terms = 65536, nip.nodes = 512: a solve takes seconds) stops
# the run from inside the solve (the series and the stick/slip passes poll the progress
# callback, util/cancel.h): exit 130, "interrupted", no file, in under 2 s (measured
# 0.2-0.6 s; the whole solve took 3.5 s at 400 nodes before, and 99999999 terms minutes).
set -u
set -m
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib.sh" # fail
"$bin" run "$scene" -o "$tmp/out.h5" --set nip.terms=65536 --set nip.nodes=512 > "$tmp/log" 2>&1 &
pid=$!
sleep 2
t0=$(date +%s.%N)
kill -INT "$pid"
wait "$pid"; got=$?
t1=$(date +%s.%N)
cat "$tmp/log"
took=$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')
echo "exit status: $got (expected 130) after $took s"
[ "$got" -eq 130 ] || fail "wrong exit status"
awk -v t="$took" 'BEGIN { exit !(t < 2) }' || fail "took $took s"
grep -q 'interrupted' "$tmp/log" || fail "no 'interrupted' message"
[ "$(ls -A "$tmp")" = log ] || fail "stray files"
echo PASS

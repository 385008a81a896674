#!/usr/bin/env bash
# plot_interrupt.sh REELSIM SCENE SIGNAL STATUS: a signal to `reelsim plot` while gnuplot
# runs (a stand-in that never finishes) stops gnuplot, removes the session's temporary
# folder (TMPDIR/reelsim-plot-*) and the output folder it made, and exits with STATUS
# within a second.
set -u
set -m
bin="$1"; scene="$2"; sig="$3"; want="$4"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib.sh" # fail, run, has
mkdir "$tmp/t" "$tmp/fake"
"$bin" run "$scene" -o "$tmp/s.h5" -q || fail "run failed"
printf '#!/bin/sh\necho $$ > "%s/gnuplot.pid"\nexec sleep 60\n' "$tmp" > "$tmp/fake/gnuplot"
chmod +x "$tmp/fake/gnuplot"
TMPDIR="$tmp/t" PATH="$tmp/fake:$PATH" "$bin" plot "$tmp/s.h5" -o "$tmp/png/deeper" > "$tmp/log" 2>&1 &
pid=$!
for i in $(seq 50); do [ -s "$tmp/gnuplot.pid" ] && break; sleep 0.1; done
[ -s "$tmp/gnuplot.pid" ] || fail "gnuplot was not started"
[ -n "$(ls -A "$tmp/t")" ] || fail "no session folder while gnuplot runs"
t0=$(date +%s.%N)
kill -"$sig" "$pid"
wait "$pid"; got=$?
t1=$(date +%s.%N)
cat "$tmp/log"
echo "exit status: $got (expected $want) after $(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }') s"
[ "$got" -eq "$want" ] || fail "wrong exit status"
awk -v a="$t0" -v b="$t1" 'BEGIN { exit !(b - a < 1) }' || fail "took a second or more"
grep -Eq "reelsim: plot: (interrupted|terminated \(SIG$sig\)) \(no plots written\)" "$tmp/log" || fail "no message"
[ -z "$(ls -A "$tmp/t")" ] || { ls -laR "$tmp/t"; fail "a temporary folder was left"; }
[ ! -e "$tmp/png" ] || fail "the output folder made for the plots was left"
kill -0 "$(cat "$tmp/gnuplot.pid")" 2>/dev/null && fail "gnuplot still runs"
echo PASS

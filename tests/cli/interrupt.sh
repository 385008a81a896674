#!/usr/bin/env bash
# interrupt.sh REELSIM SCENE [SIGNAL STATUS [--keep-partial | study]]: a signal (default
# INT, i.e. Ctrl-C; TERM gives 143) during `run` stops it after the current step, says
# where it stopped, and exits with STATUS (default 130; HUP and QUIT as TERM: 129, 131). It writes no file, or with
# --keep-partial exactly the output file, marked complete = 0, with the layers the message
# names. `study`: the same signal during `reelsim study -o DIR` (DIR two levels below
# anything that exists) stops it after the runs in progress with `study: interrupted` (or
# `terminated (SIGTERM)`) and STATUS, and leaves no file and no directory: DIR is made
# only when the study has something to write.
set -u
set -m   # job control: the background run gets SIGINT like a foreground one would
bin="$1"; scene="$2"; sig="${3:-INT}"; want="${4:-130}"; keep="${5:-}"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
# a reel long enough (13 s on the 2-core machine) that the signal lands mid-run even where runs
# are faster: 41,800 layers, each increment integrated from the core at rtol 1e-9
if [ "$keep" = study ]; then
  "$bin" study "$scene" --set winding.final_radius=1.5 -o "$tmp/out/study" > "$tmp/log" 2>&1 &
else
  "$bin" run "$scene" --set winding.final_radius=3 --set numerics.reuse=none \
    --set numerics.rtol=1e-9 -o "$tmp/out.h5" $keep > "$tmp/log" 2>&1 &
fi
pid=$!
sleep 1
kill -"$sig" "$pid"
wait "$pid"; got=$?
cat "$tmp/log"
echo "exit status: $got (expected $want)"
[ "$got" -eq "$want" ] || { echo "FAIL: wrong exit status"; exit 1; }
word=interrupted; [ "$sig" != INT ] && word="terminated \\(SIG$sig\\)"
if [ "$keep" = study ]; then
  grep -Eq "reelsim: study: $word \(no output written\)" "$tmp/log" ||
    { echo "FAIL: no 'study: $word (no output written)' message"; exit 1; }
  [ "$(ls -A "$tmp")" = "log" ] || { ls -laR "$tmp"; echo "FAIL: stray files or directories"; exit 1; }
elif [ -z "$keep" ]; then
  grep -Eq "reelsim: $word at layer [0-9]+ of [0-9]+ \(no output written\)" "$tmp/log" ||
    { echo "FAIL: no '$word at layer k of N (no output written)' message"; exit 1; }
  [ ! -e "$tmp/out.h5" ] || { echo "FAIL: an output file was written"; exit 1; }
  [ "$(ls -A "$tmp")" = "log" ] || { ls -la "$tmp"; echo "FAIL: stray files"; exit 1; }
else
  k="$(sed -nE "s/.*$word at layer ([0-9]+) of [0-9]+ \(partial result written to .*, complete = 0\).*/\1/p" "$tmp/log")"
  [ -n "$k" ] || { echo "FAIL: no 'partial result written' message"; exit 1; }
  h5dump -a complete "$tmp/out.h5" | grep -Eq '\(0\): 0$' || { echo "FAIL: complete is not 0"; exit 1; }
  h5dump -a layers "$tmp/out.h5" | grep -Eq "\(0\): $k\$" || { echo "FAIL: layers is not $k"; exit 1; }
  [ "$(ls -A "$tmp" | sort | tr '\n' ' ')" = "log out.h5 " ] || { ls -la "$tmp"; echo "FAIL: stray files"; exit 1; }
fi
echo PASS

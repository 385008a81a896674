#!/usr/bin/env bash
# compare.sh REELSIM SCENES CASE: `reelsim compare` end to end (SCENES = tests/cli/scenes).
#   identical       two copies of one scene: exit 0, a table, one file that h5dump reads,
#                   both runs bitwise equal (h5diff, /summary to 17 digits)
#   bad_scene       a bad scene among good ones: exit 2 naming it, nothing wound, no file
#   solver_failure  one run cannot be wound: exit 3, the others still reported, no file
#   default_name    no -o: compare.h5 in the working directory; --quiet prints nothing
#   missing_dir     -o into a missing directory: exit 1 before any winding
#   interrupted     Ctrl-C: exit 130, no file
set -u
bin="$1"; sc="$2"; case="$3"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
w="$tmp/w"; mkdir "$w"   # where outputs go; logs stay beside it
. "$(dirname "$0")/lib.sh" # fail, run, has, is_png
no_files() { [ -z "$(ls -A "$w")" ] || { ls -la "$w"; fail "files were written"; }; }

case "$case" in
identical)
  run "$bin" compare "$sc/small.yaml" "$sc/small.yaml" -o "$w/cmp.h5"
  [ "$got" -eq 0 ] || fail "exit status $got, expected 0"
  has '^compare: 2 scenes on [12] threads?$'
  has '^1-small +200 +70\.0 +[0-9.]+ +[0-9.]+ '
  has '^2-small +200 +70\.0 '
  has "^output $w/cmp\.h5$"
  h5dump -H "$w/cmp.h5" > "$tmp/header.txt" || fail "h5dump -H cannot read the file"
  grep -q 'GROUP "1-small"' "$tmp/header.txt" || fail "no group /runs/1-small"
  grep -q 'DATASET "core_pressure"' "$tmp/header.txt" || fail "no /summary/core_pressure"
  rm -f "$tmp/header.txt"
  for g in final layers; do
    h5diff "$w/cmp.h5" "$w/cmp.h5" "/runs/1-small/$g" "/runs/2-small/$g" ||
      fail "/runs/1-small/$g and /runs/2-small/$g differ"
  done
  for d in core_pressure peak_pressure min_hoop_stress wot_min wot_max; do
    h5dump -m '%.17g' -d "/summary/$d" -y -w 0 -o "$tmp/vals.txt" "$w/cmp.h5" > /dev/null ||
      fail "h5dump -d /summary/$d"
    vals="$(tr -d ' \n' < "$tmp/vals.txt")"; rm -f "$tmp/vals.txt"
    echo "/summary/$d: $vals"
    a="${vals%%,*}"; b="${vals##*,}"
    [ -n "$a" ] && [ "$a" = "$b" ] || fail "/summary/$d: '$a' and '$b' differ"
  done
  ;;
bad_scene)
  run "$bin" compare "$sc/small.yaml" "$sc/bad-taper.yaml" "$sc/small.yaml" -o "$w/cmp.h5"
  [ "$got" -eq 2 ] || fail "exit status $got, expected 2"
  has 'bad-taper\.yaml:9: winding\.tension\.end'
  has 'compare: nothing was wound'
  printf '%s\n' "$out" | grep -q '^compare:' && fail "a table was printed"
  no_files
  ;;
solver_failure)
  run "$bin" compare "$sc/small.yaml" "$sc/small-fail.yaml" -o "$w/cmp.h5"
  [ "$got" -eq 3 ] || fail "exit status $got, expected 3"
  has 'small-fail\.yaml: solver failure: .*CVODE'
  has '^1-small +200 +70\.0 '
  has '^2-small-fail +FAILED \(solver failure\)'
  has 'a run failed; no output written'
  no_files
  ;;
default_name)
  (cd "$w" && "$bin" compare "$sc/small.yaml" "$sc/small.yaml" --quiet > ../quiet.log 2>&1) ||
    fail "compare failed"
  [ -s "$w/compare.h5" ] || fail "no compare.h5"
  [ ! -s "$tmp/quiet.log" ] || { cat "$tmp/quiet.log"; fail "--quiet printed something"; }
  h5dump -a /runs/1-small/scene "$w/compare.h5" | grep -q 'file: compare.h5' ||
    fail "the stored scene does not name compare.h5"
  [ "$(ls -A "$w" | wc -l)" -eq 1 ] || { ls -la "$w"; fail "stray files"; }
  ;;
missing_dir)
  run "$bin" compare "$sc/small.yaml" -o "$w/nowhere/cmp.h5"
  [ "$got" -eq 1 ] || fail "exit status $got, expected 1"
  has "directory '$w/nowhere' does not exist"
  printf '%s\n' "$out" | grep -q '^compare:' && fail "it wound before checking the target"
  no_files
  ;;
interrupted)
  set -m   # job control: the background run gets SIGINT like a foreground one would
  # a run of ten seconds or more (59,500 layers at rtol 1e-9), so that the signal lands
  # mid-run even on a fast machine; a constant modulus lets every increment reuse the deep
  # solution (numerics.reuse), so that is off here
  "$bin" compare "$sc/small.yaml" "$sc/small.yaml" --set winding.final_radius=6 \
    --set numerics.rtol=1e-9 --set numerics.reuse=none -o "$w/cmp.h5" > "$tmp/log" 2>&1 &
  pid=$!
  sleep 1
  kill -INT "$pid"
  wait "$pid"; got=$?
  out="$(cat "$tmp/log")"
  printf '%s\n' "$out"; echo "exit status: $got"
  [ "$got" -eq 130 ] || fail "exit status $got, expected 130"
  has 'compare: interrupted \(no output written\)'
  no_files
  ;;
*) fail "unknown case $case" ;;
esac
echo PASS

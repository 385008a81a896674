#!/usr/bin/env bash
# plot.sh REELSIM SCENES CASE: `reelsim plot` end to end with the real gnuplot (the PNG
# contents are checked by test_plot).
#   run_file      a run's file: three PNGs listed and written, nothing else left
#   compare_file  a comparison's file: three overlays
#   no_gnuplot    gnuplot not on PATH: exit 1 with the install hint, nothing written,
#                 no temporary directory left
#   not_reelsim   an HDF5 file reelsim did not write: exit 2 naming it
#   missing_dir   -o into a directory that does not exist, two levels deep: made as with
#                 mkdir -p, the PNGs written there
#   not_dir       -o onto a file, or below one: exit 2 naming it, nothing written
#   bad_file_dir  a file that is not a reelsim file, -o into a missing directory: exit 2,
#                 and the directory made for it is removed again
set -u
bin="$1"; sc="$2"; case="$3"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib.sh" # fail, run, has, is_png

mkdir "$tmp/png" "$tmp/t"
export TMPDIR="$tmp/t"
"$bin" run "$sc/small.yaml" -o "$tmp/small.h5" --quiet || fail "run failed"
case "$case" in
run_file)
  run "$bin" plot "$tmp/small.h5" -o "$tmp/png"
  [ "$got" -eq 0 ] || fail "exit status $got, expected 0"
  for p in pressure hoop tension; do
    has "^$tmp/png/small-$p\.png$"
    is_png "$tmp/png/small-$p.png"
  done
  [ "$(ls -A "$tmp/png" | wc -l)" -eq 3 ] || { ls -la "$tmp/png"; fail "stray files"; }
  ;;
compare_file)
  "$bin" compare "$sc/small.yaml" "$sc/small.yaml" -o "$tmp/cmp.h5" --quiet || fail "compare"
  run "$bin" plot "$tmp/cmp.h5" -o "$tmp/png"
  [ "$got" -eq 0 ] || fail "exit status $got, expected 0"
  for p in pressure hoop tension; do is_png "$tmp/png/cmp-$p.png"; done
  ;;
no_gnuplot)
  run env PATH=/nonexistent "$bin" plot "$tmp/small.h5" -o "$tmp/png"
  [ "$got" -eq 1 ] || fail "exit status $got, expected 1"
  has 'gnuplot not found \(apt-get install gnuplot-nox\)'
  [ -z "$(ls -A "$tmp/png")" ] || fail "files were written"
  ;;
not_reelsim)
  h5copy -i "$tmp/small.h5" -o "$tmp/foreign.h5" -s /final -d /final || fail "h5copy"
  run "$bin" plot "$tmp/foreign.h5" -o "$tmp/png"
  [ "$got" -eq 2 ] || fail "exit status $got, expected 2"
  has "'$tmp/foreign\.h5' is an HDF5 file but not a reelsim file"
  ;;
missing_dir)
  run "$bin" plot "$tmp/small.h5" -o "$tmp/nowhere/deeper"
  [ "$got" -eq 0 ] || fail "exit status $got, expected 0"
  for p in pressure hoop tension; do is_png "$tmp/nowhere/deeper/small-$p.png"; done
  [ "$(ls -A "$tmp/nowhere/deeper" | wc -l)" -eq 3 ] || fail "stray files"
  ;;
not_dir)
  run "$bin" plot "$tmp/small.h5" -o "$tmp/small.h5"
  [ "$got" -eq 2 ] || fail "exit status $got, expected 2"
  has "reelsim: plot: output directory '$tmp/small\.h5' is not a directory"
  run "$bin" plot "$tmp/small.h5" -o "$tmp/small.h5/png"
  [ "$got" -eq 2 ] || fail "exit status $got, expected 2"
  has "reelsim: plot: output directory '$tmp/small\.h5/png': '$tmp/small\.h5' is not a directory"
  [ "$(ls -A "$tmp" | tr '\n' ' ')" = "png small.h5 t " ] || { ls -la "$tmp"; fail "stray files"; }
  [ -z "$(ls -A "$tmp/png")" ] || fail "PNGs written"
  ;;
bad_file_dir)
  run "$bin" plot "$sc/small.yaml" -o "$tmp/made/here"
  [ "$got" -eq 2 ] || fail "exit status $got, expected 2"
  has "is not an HDF5 file"
  [ ! -e "$tmp/made" ] || fail "the directory made for a failed plot was left"
  ;;
*) fail "unknown case $case" ;;
esac
[ -z "$(ls -A "$tmp/t")" ] || { ls -la "$tmp/t"; fail "a temporary directory was left"; }
echo PASS

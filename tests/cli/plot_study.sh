#!/usr/bin/env bash
# plot_study.sh REELSIM SCENE: `reelsim plot study.h5` draws the study's picture from the
# file (DIR/study-study.png), the same PNG, byte for byte, that the study drew from its
# runs (gnuplot given the same numbers: the file keeps every double); a run file still
# gets the run plots, and a file that is neither is still refused (exit 2).
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
command -v gnuplot >/dev/null || { echo "gnuplot not available: skipped"; exit 77; }
run "$bin" study "$scene" --quick -o "$tmp/st" --quiet
[ "$got" -eq 0 ] || fail "study: exit $got"
run "$bin" plot "$tmp/st/study.h5" -o "$tmp/pl"
[ "$got" -eq 0 ] || fail "plot study.h5: exit $got"
has "^$tmp/pl/study-study\\.png\$"
is_png "$tmp/pl/study-study.png"
cmp "$tmp/st/study.png" "$tmp/pl/study-study.png" || fail "not the study's own picture"
run "$bin" plot "$tmp/st/study.csv" -o "$tmp/pl"
[ "$got" -eq 2 ] || fail "plot of a CSV: exit $got, expected 2"
echo PASS

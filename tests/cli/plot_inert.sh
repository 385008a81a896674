#!/usr/bin/env bash
# plot_inert.sh REELSIM SCENE CASE: strings from a scene or a file reach gnuplot inert
# (issue 36). Titles and run names hold backquotes, system("..."), @macros, newlines and
# quotes, each asking gnuplot to create a marker file; the plots are made and no marker is.
#   run_title      a run's title (--set title=...) plotted by `reelsim plot`
#   compare_names  compare's run names, which come from the scene files' names
#   study_title    `reelsim study` plots by itself: a hostile title in the scene
set -u
bin="$1"; scene="$2"; case="$3"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib.sh" # fail, run, has, is_png
cd "$tmp" || fail "cd"
# every way gnuplot could run something: `cmd` substitution, system(), a macro, a quote
# or a newline that would end the string and start a command of its own
evil='x `touch m1` system("touch m2") @evil '"'"' ; system("touch m3") ; '"'"'
" ; system("touch m4") ; "
system("touch m5") \'
no_marker() {
  for m in m1 m2 m3 m4 m5; do [ ! -e "$tmp/$m" ] || fail "gnuplot ran a command: $m made"; done
}
case "$case" in
run_title)
  "$bin" run "$scene" -o "$tmp/run.h5" --quiet --set "title=$evil" || fail "run failed"
  run "$bin" plot "$tmp/run.h5" -o "$tmp/png"
  [ "$got" -eq 0 ] || fail "exit status $got, expected 0"
  for p in pressure hoop tension; do is_png "$tmp/png/run-$p.png"; done
  ;;
compare_names)
  a='a`touch m1`'"'"'b'; b='c" ; system("touch m2") ; "d'
  cp "$scene" "$tmp/$a.yaml"; cp "$scene" "$tmp/$b.yaml"
  run "$bin" compare "$tmp/$a.yaml" "$tmp/$b.yaml" -o "$tmp/cmp.h5" --quiet
  [ "$got" -eq 0 ] || fail "compare failed"
  run "$bin" plot "$tmp/cmp.h5" -o "$tmp/png"
  [ "$got" -eq 0 ] || fail "exit status $got, expected 0"
  for p in pressure hoop tension; do is_png "$tmp/png/cmp-$p.png"; done
  ;;
study_title)
  { printf 'title: %s\n' "'$(printf '%s' "$evil" | tr '\n' ' ' | sed "s/'/''/g")'"
    grep -v '^title:' "$scene"; } > "$tmp/s.yaml"
  run "$bin" study "$tmp/s.yaml" -o "$tmp/study" --quiet
  [ "$got" -eq 0 ] || fail "study failed"
  ls "$tmp/study"/*.png > /dev/null 2>&1 || fail "study made no PNG"
  for p in "$tmp/study"/*.png; do is_png "$p"; done
  ;;
*) fail "unknown case $case" ;;
esac
no_marker
echo PASS

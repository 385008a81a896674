#!/usr/bin/env bash
# run_outputs.sh REELSIM SCENE CASE: where a run may write (issue 36).
#   same_file    run s.yaml -o s.yaml (also ./s.yaml, and a scene whose own output.file
#                names itself): exit 2, the scene unchanged
#   escape       a scene's own output.file '../x.h5' or '/abs/x.h5': exit 2 naming the
#                key and its line, nothing written; -o ../x.h5 names the path and is obeyed
#   csv_fails    run -o out.h5 --csv DIR where a CSV file cannot be written: exit 1, no new
#                out.h5 (an older one is kept as it was), no temporaries
set -u
bin="$1"; scene="$2"; case="$3"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib.sh" # fail, run, has
mkdir "$tmp/w"; cd "$tmp/w" || fail "cd"
grep -v '^output:' "$scene" > s.yaml
sum0=$(md5sum < s.yaml)
case "$case" in
same_file)
  for o in s.yaml ./s.yaml "$tmp/w/s.yaml"; do
    run "$bin" run s.yaml -o "$o"
    [ "$got" -eq 2 ] || fail "-o $o: exit status $got, expected 2"
    has "run: the output '$o' is the input 's\.yaml' itself"
  done
  { cat s.yaml; echo 'output: {file: self.yaml}'; } > self.yaml
  run "$bin" run self.yaml
  [ "$got" -eq 2 ] || fail "exit status $got, expected 2"
  has "run: output.file 'self\.yaml' is the scene file itself"
  [ "$(md5sum < s.yaml)" = "$sum0" ] || fail "the scene was changed"
  grep -q '^output: {file: self.yaml}$' self.yaml || fail "self.yaml was changed"
  ;;
escape)
  for f in ../x.h5 sub/../../x.h5 "$tmp/x.h5"; do
    { cat s.yaml; echo "output: {file: '$f'}"; } > e.yaml
    run "$bin" run e.yaml -q
    [ "$got" -eq 2 ] || fail "$f: exit status $got, expected 2"
    has "e\.yaml:[0-9]+: output\.file: a scene's own output file must stay in the folder it is run in"
    [ ! -e "$tmp/x.h5" ] || fail "$f: written outside"
  done
  run "$bin" run e.yaml -q -o ../x.h5
  [ "$got" -eq 0 ] || fail "-o ../x.h5: exit status $got, expected 0"
  [ -f "$tmp/x.h5" ] || fail "-o ../x.h5 not written"
  ;;
csv_fails)
  mkdir -p csv/s-profile.csv   # a directory where a CSV file should go
  run "$bin" run s.yaml -q -o out.h5 --csv csv
  [ "$got" -eq 1 ] || fail "exit status $got, expected 1"
  has "csv/s-profile\.csv"
  [ ! -e out.h5 ] || fail "the HDF5 file was left behind"
  echo old > out.h5
  run "$bin" run s.yaml -q -o out.h5 --csv csv
  [ "$got" -eq 1 ] || fail "exit status $got, expected 1"
  [ "$(cat out.h5)" = old ] || fail "the older out.h5 was replaced"
  [ -z "$(find . -name '*.tmp.*')" ] || { find .; fail "temporaries left"; }
  [ "$(ls -A csv)" = s-profile.csv ] || { ls -la csv; fail "stray CSV files"; }
  ;;
*) fail "unknown case $case" ;;
esac
echo PASS

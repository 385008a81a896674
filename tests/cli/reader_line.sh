#!/usr/bin/env bash
# reader_line.sh REELSIM SCENE: bytes libyaml's reader refuses (a NUL, a byte that is not
# UTF-8, a UTF-8 sequence cut off at the end of the file) are reported at their own line and
# column, not at line 1: exit 2, "FILE:LINE: column C: why (byte 0xNN)", nothing written.
# libyaml gives only the byte offset of such a byte; the line is counted from the text.
set -u
export LC_ALL=C
. "$(dirname "$0")/lib.sh"
bin=$1 scene=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
# the scene with BYTES put in front of line LINE's text at column COL (1-based)
plant() { awk -v line="$2" -v col="$3" -v bytes="$4" 'NR == line { $0 = substr($0, 1, col - 1) bytes substr($0, col) }
                                                      { print }' "$scene" >"$1"; }
# line 9 of small.yaml is "winding:" (its comments and title above it)
[ "$(sed -n 9p "$scene")" = "winding:" ] || fail "small.yaml changed: line 9 is not 'winding:'"
plant nul.yaml 9 3 $'\x01'
{ head -n 8 "$scene"; printf 'wi\0nding:\n'; tail -n +10 "$scene"; } >nul0.yaml
plant ff.yaml 10 5 $'\xff'
{ cat "$scene"; printf '# caf\xc3'; } >cut.yaml
lines=$(($(wc -l <"$scene") + 1))
for c in "nul0.yaml 9 3 control characters are not allowed \(byte 0x00\)" \
         "nul.yaml 9 3 control characters are not allowed \(byte 0x01\)" \
         "ff.yaml 10 5 invalid leading UTF-8 octet \(byte 0xFF\)" \
         "cut.yaml $lines 6 incomplete UTF-8 octet sequence"; do
  set -- $c
  f=$1 line=$2 col=$3
  shift 3
  run "$bin" run "$f" -o "$f.h5"
  [ "$got" -eq 2 ] || fail "$f: exit $got, expected 2"
  has "^reelsim: $f:$line: column $col: $*: a scene must be UTF-8 text without control characters$"
  [ ! -e "$f.h5" ] || fail "$f: a file was written"
done
[ -z "$(ls -A | grep -v '\.yaml$')" ] || { ls -la; fail "files were left"; }
echo PASS

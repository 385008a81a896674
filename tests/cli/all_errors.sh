#!/usr/bin/env bash
# all_errors.sh REELSIM SCENE: a scene with several errors reports them all, one
# "reelsim: FILE:LINE: key.path: why" line each, in the file's order, exit 2, for check
# and run alike (run writes nothing).
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
for cmd in check run; do
  run "$bin" $cmd "$scene" -o "$tmp/x.h5"
  [ "$got" -eq 2 ] || fail "$cmd: exit status $got, expected 2"
  [ "$(printf '%s\n' "$out" | wc -l)" -eq 3 ] || fail "$cmd: expected 3 lines"
  printf '%s\n' "$out" | sed -n 1p | grep -Eq 'many-errors\.yaml:5: material\.radial\.law: unknown value .pfeifer.' || fail "line 1"
  printf '%s\n' "$out" | sed -n 2p | grep -Eq 'many-errors\.yaml:6: core\.stifness: unknown key .stifness.' || fail "line 2"
  printf '%s\n' "$out" | sed -n 3p | grep -Eq '^reelsim: .*many-errors\.yaml:9: winding\.tension: ' || fail "line 3"
  [ ! -e "$tmp/x.h5" ] || fail "$cmd wrote a file"
done
echo PASS

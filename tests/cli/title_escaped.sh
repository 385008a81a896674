#!/usr/bin/env bash
# title_escaped.sh REELSIM SCENE: control characters in a title (an escape sequence that
# would retitle the terminal, a newline that would forge a line of output) are printed as
# escapes by run, check and compare, never raw.
set -u
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib.sh" # fail
t="$(printf 'a\033]0;pwned\007b\nforged line')"
for cmd in "run $scene -o $tmp/t.h5" "check $scene" "compare $scene $scene -o $tmp/c.h5"; do
  # shellcheck disable=SC2086
  "$bin" $cmd --set "title=$t" > "$tmp/out" 2>&1 || fail "$cmd failed"
  LC_ALL=C grep -q "$(printf '\033')" "$tmp/out" && fail "$cmd: a raw ESC printed"
  grep -q '^forged line' "$tmp/out" && fail "$cmd: the newline was printed raw"
  grep -qF 'a\x1b]0;pwned\x07b\nforged line' "$tmp/out" || { cat "$tmp/out"; fail "$cmd: no escaped title"; }
done
echo PASS

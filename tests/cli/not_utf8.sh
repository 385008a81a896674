#!/usr/bin/env bash
# not_utf8.sh REELSIM SCENE: a --set value that is not UTF-8 (the shell passes any bytes)
# is bad input, exit 2 naming the --set, not an internal error of the YAML writer.
set -u
export LC_ALL=C # the byte 0xe9 is a character to grep
. "$(dirname "$0")/lib.sh"
run "$1" check "$2" --set $'title=caf\xe9'
[ "$got" -eq 2 ] || fail "exit status $got, expected 2"
has '^reelsim: --set title=caf.: not UTF-8 text$'
echo PASS

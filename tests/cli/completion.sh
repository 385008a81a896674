#!/usr/bin/env bash
# completion.sh REELSIM SCRIPT: the bash completion script (generated at build time by
# `reelsim --bash-completion`) sourced in bash: _reelsim called with COMP_WORDS/COMP_CWORD
# offers the commands, each command's flags (every --flag `reelsim CMD --help` lists, and
# no other), files of the right kind for operands and option arguments. The script is the
# one the program prints now (not a stale copy).
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; script="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
[ -f "$script" ] || fail "no $script"
"$bin" --bash-completion | cmp - "$script" || fail "$script is not what reelsim prints"
. "$script"
# complete WORD...: the candidates for the last word, one a line, sorted
complete_words() {
  COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); COMPREPLY=()
  _reelsim
  printf '%s\n' "${COMPREPLY[@]}" | sort
}
got="$(complete_words reelsim '' | tr '\n' ' ')"
for c in run check compare plot study nip help --help --version; do
  case " $got " in *" $c "*) ;; *) fail "command '$c' not offered: $got" ;; esac
done
[ "$(complete_words reelsim co | tr '\n' ' ')" = "compare " ] || fail "co -> compare"
[ "$(complete_words reelsim help pl | tr '\n' ' ')" = "plot " ] || fail "help pl -> plot"
# every command's flags are exactly the long flags its --help lists
for c in run check compare plot study nip; do
  want="$("$bin" $c --help | grep -oE '(^|[ ,])--[a-z][a-z-]*' | sed 's/^[ ,]*//' | sort -u)"
  have="$(complete_words reelsim $c -- | sort -u)"
  [ -n "$want" ] || fail "$c --help lists no flags"
  [ "$want" = "$have" ] || { echo "help:"; echo "$want"; echo "completion:"; echo "$have"; fail "$c: flags differ"; }
done
# fit parses its own arguments: its subcommands, then each one's flags as its usage lists them
[ "$(complete_words reelsim fit '' | tr '\n' ' ')" = "--help roll stack " ] || fail "fit subcommands"
for sub in stack roll; do
  want="$("$bin" fit $sub --help | grep "reelsim fit $sub" -A1 | grep -oE '(^|[ [])--?[a-z][a-z-]*' | sed 's/^[ [ ]*//' | sort -u)"
  have="$(complete_words reelsim fit $sub x -- | sort -u; complete_words reelsim fit $sub x -o | sort -u)"
  have="$(printf '%s\n' "$have" | sort -u)"
  [ -n "$want" ] || fail "fit $sub --help lists no flags"
  [ "$want" = "$have" ] || { echo "usage:"; echo "$want"; echo "completion:"; echo "$have"; fail "fit $sub: flags differ"; }
done
[ "$(complete_words reelsim fit stack x.csv --law ha | tr '\n' ' ')" = "hakiel " ] || fail "--law ha"
[ "$(complete_words reelsim run x.yaml --js | tr '\n' ' ')" = "--json " ] || fail "run --js"
[ -z "$(complete_words reelsim check --js)" ] || fail "check takes no --json"
# operands and option arguments
mkdir -p "$tmp/d/sub"; touch "$tmp/d/a.yaml" "$tmp/d/b.h5" "$tmp/d/c.txt"
cd "$tmp/d" || fail cd
[ "$(complete_words reelsim run '' | tr '\n' ' ')" = "a.yaml sub " ] || fail "run operand: $(complete_words reelsim run '')"
[ "$(complete_words reelsim plot '' | tr '\n' ' ')" = "b.h5 sub " ] || fail "plot operand: $(complete_words reelsim plot '')"
[ "$(complete_words reelsim run a.yaml --csv '' | tr '\n' ' ')" = "sub " ] || fail "--csv takes a directory"
[ "$(complete_words reelsim run a.yaml -o '' | tr '\n' ' ')" = "a.yaml b.h5 c.txt sub " ] || fail "-o FILE"
[ -z "$(complete_words reelsim study a.yaml --jobs '')" ] || fail "--jobs N offers nothing"
echo PASS

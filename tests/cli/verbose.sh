#!/usr/bin/env bash
# verbose.sh REELSIM SCENES: messages for users do not show where in the code an error was
# found ("(at check_dir (staging.c:39))"); --verbose (-v) adds that line. Checked on a
# solver failure (run), an output file that cannot be made (run, compare) and a failed
# run in a comparison.
set -u
bin="$1"; sc="$2"
. "$(dirname "$0")/lib.sh" # fail, run, has
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
where='reelsim:   \(at [A-Za-z_0-9]+ \([A-Za-z_0-9]+\.c:[0-9]+\)\)'

check() { # STATUS MESSAGE-REGEX -- ARGS...
  local want="$1" msg="$2"; shift 3
  run "$bin" "$@"
  [ "$got" -eq "$want" ] || fail "$*: exit $got, expected $want"
  has "$msg"
  printf '%s\n' "$out" | grep -Eq -- "$where" && fail "$*: a source location without --verbose"
  for v in --verbose -v; do
    run "$bin" "$@" $v
    [ "$got" -eq "$want" ] || fail "$* $v: exit $got, expected $want"
    has "$msg"
    has "$where"
  done
}

check 3 'reelsim: solver failure: winding layers 2-2 of 200' -- \
  run "$sc/small.yaml" --set numerics.max_steps=2 --set numerics.rtol=1e-5 -o "$tmp/a.h5"
check 1 "reelsim: i/o error: cannot create output file '$tmp/no/a\.h5'" -- \
  run "$sc/small.yaml" -o "$tmp/no/a.h5"
check 1 "reelsim: i/o error: cannot create output file '$tmp/no/c\.h5'" -- \
  compare "$sc/small.yaml" "$sc/small.yaml" -o "$tmp/no/c.h5"
check 3 'small\.yaml: solver failure: winding layers' -- \
  compare "$sc/small.yaml" --set numerics.max_steps=2 --set numerics.rtol=1e-5 -o "$tmp/c.h5"
[ -z "$(ls -A "$tmp")" ] || { ls -la "$tmp"; fail "files were written"; }
echo PASS

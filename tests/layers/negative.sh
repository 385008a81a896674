#!/usr/bin/env bash
# negative.sh CASE CHECK CC: builds a small tree with one violation of the layer rule
# (docs/architecture.md) and asserts that CHECK (scripts/check-layers.sh) fails on it
# naming the violation, and passes on the same tree without it.
set -euo pipefail
case_=$1 check=$2 cc=$3
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
mkdir -p "$t/include/reelsim" "$t/src/nip" "$t/src/scene" "$t/src/cli"
cat >"$t/include/reelsim/status.h" <<'H'
typedef int rs_status;
H
printf '#include "reelsim/status.h"\n' >"$t/include/reelsim/nip.h"
printf '#include "reelsim/nip.h"\n' >"$t/include/reelsim/scene.h"
printf '#include "reelsim/nip.h"\nint rs_nip_a(void) { return 1; }\n' >"$t/src/nip/a.c"
printf '#include "reelsim/nip.h"\nint rs_nip_a(void);\nint rs_nip_b(void) { return rs_nip_a(); }\n' >"$t/src/nip/b.c"
printf '#include "reelsim/scene.h"\n' >"$t/src/scene/load.c"
printf '#include "reelsim/scene.h"\n#include "cli/cli.h"\n' >"$t/src/cli/main.c"
printf '#include "reelsim/status.h"\n' >"$t/src/cli/cli.h"
objs=()

expect_pass() {
  if ! out=$(bash "$check" "$t" "${objs[@]}" 2>&1); then
    echo "FAIL: the clean tree was refused:"; echo "$out"; exit 1
  fi
}
expect_fail() { # regexes the message must match, each on some line
  if out=$(bash "$check" "$t" "${objs[@]}" 2>&1); then
    echo "FAIL: the check passed a tree with $case_:"; echo "$out"; exit 1
  fi
  echo "$out"
  for re in "$@"; do
    if ! grep -Eq -- "$re" <<<"$out"; then echo "FAIL: the message does not match /$re/"; exit 1; fi
  done
}

case "$case_" in
  lower_includes_higher) # physics including the scene (the issue's nip.h -> scene.h)
    expect_pass
    printf '#include "reelsim/scene.h"\n' >>"$t/include/reelsim/nip.h"
    expect_fail 'include/reelsim/nip.h:2: the roll-nip layer includes "reelsim/scene.h" of the higher scene layer' ;;
  internal_includes_higher) # a private header of a higher directory
    expect_pass
    printf '#include "cli/cli.h"\n' >>"$t/src/nip/a.c"
    expect_fail 'src/nip/a.c:3: the roll-nip layer includes "cli/cli.h" of the higher cli layer' ;;
  include_cycle) # two files of one layer including each other
    printf '#include "nip/b.h"\n' >"$t/src/nip/a.h"
    printf '#include "nip/c.h"\n' >"$t/src/nip/b.h"
    printf '#include "reelsim/status.h"\n' >"$t/src/nip/c.h"
    expect_pass
    printf '#include "nip/a.h"\n' >>"$t/src/nip/c.h"
    expect_fail 'include cycle' 'tsort: src/nip/a.h' 'tsort: src/nip/c.h' ;;
  cli_internal_header) # the CLI past the public API
    expect_pass
    printf '#include "nip/internal.h"\n' >>"$t/src/cli/main.c"
    printf '#include "reelsim/status.h"\n' >"$t/src/nip/internal.h"
    expect_fail 'src/cli/main.c:3: the CLI includes "nip/internal.h", not a public header' ;;
  unplaced) # a directory the map does not know
    expect_pass
    mkdir -p "$t/src/gadget"
    printf '#include "reelsim/status.h"\n' >"$t/src/gadget/gadget.c"
    expect_fail 'src/gadget/gadget.c: not placed in a layer' ;;
  call_cycle) # a.c and b.c calling each other, one header declaring both
    "$cc" -c -o "$t/src/nip/a.c.o" -I"$t/include" "$t/src/nip/a.c"
    "$cc" -c -o "$t/src/nip/b.c.o" -I"$t/include" "$t/src/nip/b.c"
    objs=("$t/src/nip/a.c.o" "$t/src/nip/b.c.o")
    expect_pass
    printf 'int rs_nip_b(void);\nint rs_nip_c(void) { return rs_nip_b(); }\n' >>"$t/src/nip/a.c"
    "$cc" -c -o "$t/src/nip/a.c.o" -I"$t/include" "$t/src/nip/a.c"
    expect_fail 'call cycle between object files' 'tsort: nip/a$' 'tsort: nip/b$' ;;
  call_upwards) # physics calling the scene through a local prototype, no #include
    "$cc" -c -o "$t/src/nip/a.c.o" -I"$t/include" "$t/src/nip/a.c"
    printf 'int rs_scene_x(void) { return 2; }\n' >>"$t/src/scene/load.c"
    "$cc" -c -o "$t/src/scene/load.c.o" -I"$t/include" "$t/src/scene/load.c"
    objs=("$t/src/nip/a.c.o" "$t/src/scene/load.c.o")
    expect_pass
    printf 'int rs_scene_x(void);\nint rs_nip_d(void) { return rs_scene_x(); }\n' >>"$t/src/nip/a.c"
    "$cc" -c -o "$t/src/nip/a.c.o" -I"$t/include" "$t/src/nip/a.c"
    expect_fail 'src/nip/a.c calls rs_scene_x of src/scene/load.c: the roll-nip layer calls the higher scene layer' ;;
  *) echo "unknown case $case_"; exit 2 ;;
esac
echo "ok: $case_ refused"

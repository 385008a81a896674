#!/usr/bin/env bash
# units_switch.sh REELSIM AIR_SCENE: --set air=false switches the scene's air off (no
# entrained-air line in check's effects), --set air=true keeps its mapping as it is.
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; scene="$2"
on="$("$bin" check "$scene" 2>&1)" || fail "check: exit $?"
printf '%s\n' "$on" | grep -q 'entrained air: film' || fail "the scene has no air to switch off"
off="$("$bin" check "$scene" --set air=false 2>&1)" || fail "check --set air=false: exit $?"
printf '%s\n' "$off" | grep -q 'entrained air' && fail "air=false left the air on"
same="$("$bin" check "$scene" --set air=true 2>&1)" || fail "check --set air=true: exit $?"
[ "$(printf '%s\n' "$same" | grep -v '^# --set')" = "$(printf '%s\n' "$on")" ] \
  || fail "air=true changed a scene that has air"
echo PASS

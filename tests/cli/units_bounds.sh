#!/usr/bin/env bash
# units_bounds.sh REELSIM SMALL_SCENE: finite absurd values (issue 36 item 6) are refused
# when the scene is read, exit 2, naming the key and the bound, with no solver coordinate
# (CVODE's "t =", "h =") in the message, and nothing written.
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; small="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
for case in "material.E_theta=1e308|above the plausible bound 1e13 Pa" \
            "material.radial.E_r=1e-320|below the plausible bound 1 Pa" \
            "numerics.rtol=1e-320|below the plausible bound 1e-12" \
            "core.radius=1e-300|below the plausible bound 0.001 m" \
            "winding.tension=1e300|above the plausible bound 1e7 N/m"; do
  set="${case%%|*}"; want="${case#*|}"
  out="$("$bin" run "$small" -o "$tmp/o.h5" --set "$set" 2>&1)"; rc=$?
  echo "$set -> $rc: $out"
  [ "$rc" -eq 2 ] || fail "$set: exit $rc, expected 2"
  printf '%s' "$out" | grep -qF -- "$want" || fail "$set: no '$want'"
  printf '%s' "$out" | grep -qE '(^|[^a-z])(t|h) = ' && fail "$set: a solver coordinate in the message"
  [ -e "$tmp/o.h5" ] && fail "$set: a file was written"
done
echo PASS

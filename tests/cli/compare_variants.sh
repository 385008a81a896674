#!/usr/bin/env bash
# compare_variants.sh REELSIM SCENE: compare --variant (docs/cli.md): a scene followed by
# variants runs as its variants, each named and with its overrides after --set; 'NAME' alone
# is the scene as it is; variants mix with whole scenes; bad variants are refused (exit 2,
# nothing written).
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; scene="$2"; cases="$(dirname "$scene")"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
py=/usr/bin/python3; [ -x "$py" ] || py=python3

run "$bin" compare "$scene" --variant 'base' --variant 'lo: winding.tension=100; core.rating=4e6' \
  --variant 'two: winding.tension=120 title=Two words' "$cases/newsprint-rider.yaml" \
  --set winding.final_radius=0.1 -o "$tmp/v.h5" --csv "$tmp/csv"
[ "$got" = 0 ] || fail "compare with variants: exit $got"
has '^  1-base +PET film'
has '^  3-two +Two words'
has '^4-newsprint-rider '
[ -f "$tmp/csv/2-lo-profile.csv" ] || fail "compare --csv: $(ls "$tmp/csv")"
"$py" - "$tmp/v.h5" <<'PY' || fail "the variants' runs"
import sys, h5py
f = h5py.File(sys.argv[1], "r")
assert list(f["summary/run"].asstr()[()]) == ["1-base", "2-lo", "3-two", "4-newsprint-rider"]
wot = [f["runs/%s/layers/wound_on_tension" % r][()][0] for r in ("1-base", "2-lo", "3-two")]
assert wot == [150.0, 100.0, 120.0], wot
scene = f["runs/2-lo"].attrs["scene"]
scene = scene.decode() if isinstance(scene, bytes) else scene
assert "rating: 4000000" in scene or "rating: 4e6" in scene or "4.0e+06" in scene, scene
assert abs(f["runs/1-base/final/core_pressure"][()] - f["runs/4-newsprint-rider/final/core_pressure"][()]) > 0
PY

# --json: each variant's run names its variant and carries its storage
run "$bin" compare "$scene" --variant 'lo: winding.tension=100' --set winding.final_radius=0.1 \
  -o "$tmp/j.h5" --json
[ "$got" = 0 ] || fail "compare --json: exit $got"
printf '%s\n' "$out" | grep -v '^exit status' | "$py" -c '
import json, sys
j = json.loads(sys.stdin.read())
r = j["runs"][0]
assert r["name"] == "1-lo" and r["variant"] == "lo: winding.tension=100", r["name"]
assert r["storage"]["stages"] == 5 and r["storage"]["core_pressure"][0] == r["core_pressure"]
' || fail "compare --json of a variant"

# the base alone is a compare of one run; a variant's bad key names the variant
run "$bin" compare "$scene" --variant 'only' --set winding.final_radius=0.1 -o "$tmp/one.h5" -q
[ "$got" = 0 ] && [ -f "$tmp/one.h5" ] || fail "one variant: exit $got"
run "$bin" compare --variant 'x: winding.tension=1' "$scene" -o "$tmp/bad1.h5"
[ "$got" = 2 ] || fail "variant before a scene: exit $got"; has "comes before any scene"
run "$bin" compare "$scene" --variant 'a.b: winding.tension=1' -o "$tmp/bad2.h5"
[ "$got" = 2 ] || fail "bad name: exit $got"; has "the name before ':' must be"
run "$bin" compare "$scene" --variant 'x: 84' -o "$tmp/bad3.h5"
[ "$got" = 2 ] || fail "not KEY=VALUE: exit $got"; has "'84' is not KEY=VALUE"
run "$bin" compare "$scene" --variant 'x: winding.tension=-5' -o "$tmp/bad4.h5"
[ "$got" = 2 ] || fail "bad value: exit $got"; has "--variant 'x: winding.tension=-5'"
ls "$tmp"/bad*.h5 >/dev/null 2>&1 && fail "a refused compare wrote a file"
echo PASS

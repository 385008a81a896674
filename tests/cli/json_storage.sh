#!/usr/bin/env bash
# json_storage.sh REELSIM STORAGE_SCENE: `run --json` on a scene with storage stages gives a
# "storage" object (docs/cli.md, JSON): S = stages + 1 entries per array, stage 0 equal to
# the run's own core pressure, the worst stage of each rule and one defect object per
# stage; a scene without storage gives "storage": null.
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
py=/usr/bin/python3; [ -x "$py" ] || py=python3
"$bin" run "$scene" --json -o "$tmp/s.h5" --set winding.final_radius=0.1 >"$tmp/run.json" \
  || fail "run --json: exit $?"
"$py" - "$tmp/run.json" <<'PY' || fail "storage fields"
import json, sys
def no_const(c): raise ValueError("non-finite number " + c)
j = json.loads(open(sys.argv[1]).read(), parse_constant=no_const)
s = j["storage"]
S = s["stages"] + 1
assert s["stages"] == 5, s["stages"]
for k in ("hours", "temperature", "humidity", "core_pressure"):
    assert len(s[k]) == S, (k, s[k])
assert s["hours"][0] == 0 and s["hours"] == sorted(s["hours"]), s["hours"]
assert s["core_pressure"][0] == j["core_pressure"], (s["core_pressure"][0], j["core_pressure"])
assert len(s["defects"]) == S and all(d["hoop"]["verdict"] in ("ok", "present") for d in s["defects"])
w = s["worst_stage"]
assert set(w) == {"hoop", "starring", "pressure", "slip", "core"}, w
assert all(-1 <= v < S for v in w.values()), w
# the hoop rule's worst stage holds the least hoop stress of all stages
least = min(d["hoop"]["min"] for d in s["defects"])
assert s["defects"][w["hoop"]]["hoop"]["min"] == least, (w, least)
print("storage:", s["stages"], "stages, worst", w)
PY
"$bin" run "$(dirname "$scene")/newsprint-rider.yaml" --json -o "$tmp/n.h5" \
  --set winding.final_radius=0.1 >"$tmp/n.json" || fail "run --json without storage"
"$py" -c 'import json,sys; assert json.load(open(sys.argv[1]))["storage"] is None' "$tmp/n.json" \
  || fail "storage is not null without storage stages"
echo PASS

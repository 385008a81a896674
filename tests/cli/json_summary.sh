#!/usr/bin/env bash
# json_summary.sh REELSIM SMALL_SCENE TOPWEB_SCENE: `run --json` and `compare --json` print
# one JSON object on stdout (nothing else there), parsed by Python's json module with NaN
# and Infinity refused, with the fields docs/cli.md promises: figures consistent with each
# other and with closed forms, defect verdicts, the output path; strings escaped so a title
# with quotes, a backslash, a tab and a byte that is not UTF-8 reads back.
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; small="$2"; topweb="$3"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
command -v python3 >/dev/null || fail "python3 is needed"

title=$'a "quoted" \\ title\twith tab \x01 end'
scene="$tmp/"$'sm\xffall.yaml'    # a file name that is not UTF-8
cp "$small" "$scene"
"$bin" run "$scene" --json -o "$tmp/s.h5" --csv "$tmp/csv" --set "title=$title" \
  >"$tmp/run.json" 2>"$tmp/run.err" || { cat "$tmp/run.err"; fail "run --json: exit $?"; }
cat "$tmp/run.json"
[ -s "$tmp/run.err" ] && { cat "$tmp/run.err"; fail "run --json wrote to stderr"; }
# the only output is one object: json.loads takes the whole of stdout
python3 - "$tmp" <<'PY' || fail "run --json fields"
import json, math, sys
tmp = sys.argv[1]
def no_const(c): raise ValueError("non-finite number " + c)
j = json.loads(open(tmp + "/run.json", encoding="utf-8").read(), parse_constant=no_const)
assert j["command"] == "run", j["command"]
assert j["title"] == 'a "quoted" \\ title\twith tab \x01 end', repr(j["title"])
assert j["scene"] == tmp + "/sm\ufffdall.yaml", repr(j["scene"])
assert j["output"] == tmp + "/s.h5"
assert j["csv"] == [tmp + "/csv/sm\ufffdall-profile.csv", tmp + "/csv/sm\ufffdall-wot.csv"], j["csv"]
assert j["layers"] == 200 and isinstance(j["layers"], int)
assert j["core_radius"] == 0.05
assert abs(j["final_radius"] - 0.07) < 1e-12, j["final_radius"]
assert j["free_diameter"] == 2 * j["final_radius"]
assert 0 < j["final_diameter"] < j["free_diameter"]  # the deformed diameter (docs/calibrate.md)
# 200 layers of 100 um from r = 0.05: sum of mid circumferences = pi (r1^2 - rc^2) / t
L = math.pi * (0.07**2 - 0.05**2) / 100e-6
assert abs(j["wound_length"] - L) < 1e-9 * L, (j["wound_length"], L)
assert j["roll_mass"] is None            # no material.density
assert j["core_pressure"] > 0 and j["peak_pressure"] >= j["core_pressure"]
assert 0.05 <= j["peak_pressure_radius"] <= 0.07
assert j["wound_on_tension_min"] == j["wound_on_tension_max"] == 200
assert j["min_hoop_stress"] <= 200 / 100e-6
assert j["wall_seconds"] >= j["solver_seconds"] >= 0
assert j["increments"] >= 1 and j["cvode_steps"] >= 1
d = j["defects"]
verdicts = {"not assessed", "ok", "risk", "present"}
for rule in ("hoop", "starring", "pressure", "slip", "core"):
    assert d[rule]["verdict"] in verdicts, (rule, d[rule])
st = d["starring"]
assert st["criterion"] in ("none", "hoop_strength", "packet_buckling"), st
assert st["verdict"] == "ok" or st["margin_min"] is not None, st
assert d["pressure"]["verdict"] == "not assessed" and d["pressure"]["limit"] is None
assert d["core"]["rating"] is None and d["core"]["pressure"] == j["core_pressure"]
print("run --json: ok")
PY

# A density gives a roll mass: rho t L.
"$bin" run "$topweb" --json -o "$tmp/t.h5" >"$tmp/t.json" || fail "run topweb --json"
python3 - "$tmp" <<'PY' || fail "roll mass"
import json, sys
j = json.load(open(sys.argv[1] + "/t.json"))
m = 1390 * 100e-6 * j["wound_length"]
assert abs(j["roll_mass"] - m) < 1e-12 * m, (j["roll_mass"], m)
assert j["defects"]["hoop"]["verdict"] == "present"
print("roll mass: ok", j["roll_mass"])
PY

# compare --json: every run, in order, and the file written.
"$bin" compare "$small" "$topweb" --json -o "$tmp/c.h5" >"$tmp/c.json" 2>"$tmp/c.err" ||
  fail "compare --json: exit $?"
cat "$tmp/c.json"
[ -s "$tmp/c.err" ] && { cat "$tmp/c.err"; fail "compare --json wrote to stderr"; }
python3 - "$tmp" <<'PY' || fail "compare --json fields"
import json, sys
tmp = sys.argv[1]
def no_const(c): raise ValueError("non-finite number " + c)
j = json.loads(open(tmp + "/c.json").read(), parse_constant=no_const)
assert j["command"] == "compare" and j["output"] == tmp + "/c.h5"
assert j["threads"] >= 1 and j["wall_seconds"] > 0
runs = j["runs"]
assert [r["name"] for r in runs] == ["1-small", "2-pet-topweb"], [r["name"] for r in runs]
assert all(r["status"] == "ok" and r["error"] is None for r in runs)
assert runs[0]["layers"] == 200 and runs[1]["layers"] == 2430
assert runs[1]["defects"]["hoop"]["verdict"] == "present"
print("compare --json: ok")
PY
[ -f "$tmp/c.h5" ] || fail "compare --json wrote no file"
echo PASS

#!/usr/bin/env bash
# lanes_figures.sh REELSIM COMMAND BAND SMALL: the lanes' figures ridge_height,
# max_lane_pressure and slack_lanes (docs/lanes.md) of compare, sweep or optimize (COMMAND)
# equal the run's own summary (`run --json`: lanes.ridge_height, lanes.hardest.peak_pressure,
# the slack list's length) to the last bit; a thicker band raises them; a scene without
# lanes (SMALL) keeps its columns and is refused these figures (exit 2, nothing written).
# BAND: three lanes, the middle one 2 % thick (lanes.caliper[1] = 1.02).
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; cmd="$2"; band="$3"; small="$4"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
py=/usr/bin/python3; [ -x "$py" ] || py=python3

# the reference: the run's own summary
"$bin" run "$band" --json -o "$tmp/run.h5" > "$tmp/run.json" || fail "run --json failed"
"$py" - "$tmp/run.json" <<'PY' || fail "run --json lanes object"
import json, sys
l = json.load(open(sys.argv[1]))["lanes"]
assert l["max_lane_pressure"] == l["hardest"]["peak_pressure"], l
assert l["slack_lanes"] == len(l["slack"]) == 0, l
assert l["ridge_height"] > 0 and l["hardest"]["x"] == 0.45, l
print("run:", l["ridge_height"], l["max_lane_pressure"], l["slack_lanes"])
PY

case "$cmd" in
compare)
  run "$bin" compare "$band" "$small" -o "$tmp/cmp.h5"
  [ "$got" = 0 ] || fail "compare: exit $got"
  has 'lanes +count +ridge height +max lane pressure +slack lanes'
  has '^1-band +3 +0\.[0-9]{3} +[0-9]+\.[0-9]{2} +0$'
  has '^2-small +-$'
  "$bin" compare "$band" "$small" -o "$tmp/cmp2.h5" --json > "$tmp/cmp.json" || fail "compare --json"
  "$py" - "$tmp" <<'PY' || fail "compare's figures"
import json, sys, h5py, numpy as np
t = sys.argv[1]
ref = json.load(open(t + "/run.json"))["lanes"]
s = h5py.File(t + "/cmp.h5", "r")["summary"]
assert s["ridge_height"][0] == ref["ridge_height"], (s["ridge_height"][0], ref)
assert s["max_lane_pressure"][0] == ref["max_lane_pressure"]
assert s["slack_lanes"][0] == ref["slack_lanes"]
assert s["ridge_height"].attrs["units"] in (b"m", "m") and s["max_lane_pressure"].attrs["units"] in (b"Pa", "Pa")
for k in ("ridge_height", "max_lane_pressure", "slack_lanes"):
    assert np.isnan(s[k][1]), k
runs = json.load(open(t + "/cmp.json"))["runs"]
assert runs[0]["lanes"]["max_lane_pressure"] == ref["max_lane_pressure"]
assert runs[0]["lanes"]["ridge_height"] == ref["ridge_height"] and runs[1]["lanes"] is None
print("compare agrees:", ref["ridge_height"], ref["max_lane_pressure"])
PY
  # without lanes in any run: no lanes table, no lanes figures in /summary
  run "$bin" compare "$small" -o "$tmp/cmp3.h5"
  printf '%s\n' "$out" | grep -q 'ridge height' && fail "a lanes table without lanes"
  "$py" -c 'import h5py,sys; assert "ridge_height" not in h5py.File(sys.argv[1])["summary"]' \
    "$tmp/cmp3.h5" || fail "lanes figures in a comparison without lanes"
  ;;
sweep)
  run "$bin" sweep "$band" --vary 'lanes.caliper[1]=1.0,1.01,1.02,1.03' -o "$tmp/sw.h5" --csv "$tmp/sw.csv"
  [ "$got" = 0 ] || fail "sweep: exit $got"
  head -1 "$tmp/sw.csv" | grep -q ',wall_seconds,status,ridge_height,max_lane_pressure,slack_lanes$' \
    || fail "sweep CSV header: $(head -1 "$tmp/sw.csv")"
  "$py" - "$tmp" <<'PY' || fail "sweep's figures"
import csv, json, sys, h5py
t = sys.argv[1]
ref = json.load(open(t + "/run.json"))["lanes"]
rows = list(csv.DictReader(open(t + "/sw.csv")))
f = h5py.File(t + "/sw.h5", "r")["sweep/figures"]
r = [x for x in rows if float(x["lanes.caliper[1]"]) == 1.02][0]   # the scene as it is
assert float(r["ridge_height"]) == ref["ridge_height"], (r["ridge_height"], ref)
assert float(r["max_lane_pressure"]) == ref["max_lane_pressure"]
assert int(r["slack_lanes"]) == ref["slack_lanes"]
assert f["max_lane_pressure"][2] == ref["max_lane_pressure"]
assert f["ridge_height"].attrs["units"] in (b"m", "m")
# the trend: a thicker band runs harder and higher; at 3 % the two thin lanes go slack
p = [float(x["max_lane_pressure"]) for x in rows]
h = [float(x["ridge_height"]) for x in rows]
assert all(a < b for a, b in zip(p, p[1:])), p
assert h[0] == 0 and all(a < b for a, b in zip(h, h[1:])), h
assert [int(x["slack_lanes"]) for x in rows] == [0, 0, 0, 2], rows
print("sweep: max_lane_pressure", p, "ridge_height", h)
PY
  # a scene without lanes keeps the columns it had
  run "$bin" sweep "$small" --vary winding.tension=100,200 -o "$tmp/sw2.h5" --csv "$tmp/sw2.csv"
  head -1 "$tmp/sw2.csv" | grep -q ',wall_seconds,status$' || fail "a scene without lanes gained columns"
  ;;
optimize)
  # the thickest band under a lane pressure limit: between 1 % (377 kPa) and 2 % (512 kPa)
  run "$bin" optimize "$band" --vary 'lanes.caliper[1]=1.0:1.04' --maximize 'lanes.caliper[1]' \
    --subject-to 'max_lane_pressure<=450e3' --subject-to 'slack_lanes<=0' -o "$tmp/best.yaml"
  [ "$got" = 0 ] || fail "optimize: exit $got"
  has 'run phase +lanes.caliper\[1\] +lanes.caliper\[1\] +max_lane_pressure +slack_lanes'
  has '^  ridge_height +[0-9.e+-]+ m$'
  has '^  slack_lanes +0$'
  "$py" - "$tmp" <<'PY' || fail "optimize's figures"
import json, sys, h5py
t = sys.argv[1]
f = h5py.File(t + "/best.h5", "r")["optimize"]
b = int(f["best"][()])
v = f["values"][()][:, 0]
p = f["figures/max_lane_pressure"][()]
assert p[b] <= 450e3 and 1.01 < v[b] < 1.02, (v[b], p[b])
order = v.argsort()
assert all(p[order][i] < p[order][i + 1] for i in range(len(v) - 1)), (v[order], p[order])
assert "ridge_height" in f["figures"] and "slack_lanes" in f["figures"]
print("optimize: best caliper factor", v[b], "at", p[b], "Pa")
PY
  # the best scene wound by run has the history's figures
  "$bin" run "$tmp/best.yaml" --json -o "$tmp/best-run.h5" > "$tmp/best.json" || fail "run best.yaml"
  "$py" - "$tmp" <<'PY' || fail "the best run's summary"
import json, sys, h5py
t = sys.argv[1]
f = h5py.File(t + "/best.h5", "r")["optimize"]
b = int(f["best"][()])
l = json.load(open(t + "/best.json"))["lanes"]
assert f["figures/max_lane_pressure"][b] == l["max_lane_pressure"], (f["figures/max_lane_pressure"][b], l)
assert f["figures/ridge_height"][b] == l["ridge_height"]
PY
  # a scene without lanes: the lanes' figures are refused before anything is wound
  for fig in ridge_height max_lane_pressure slack_lanes; do
    run "$bin" optimize "$small" --vary winding.tension=100:300 --minimize "$fig" -o "$tmp/no.yaml"
    [ "$got" = 2 ] || fail "$fig without lanes: exit $got"
    has "optimize: $fig: .*small\.yaml has no \`lanes:\` \(docs/lanes\.md\)"
  done
  run "$bin" optimize "$small" --vary winding.tension=100:300 --minimize core_pressure \
    --subject-to 'max_lane_pressure<=1e6' -o "$tmp/no.yaml"
  [ "$got" = 2 ] || fail "a lanes constraint without lanes: exit $got"
  [ -e "$tmp/no.h5" ] || [ -e "$tmp/no.yaml" ] && fail "a refused optimize wrote a file"
  # ... and absent from the history of a scene without them
  run "$bin" optimize "$small" --vary winding.tension=100:300 --minimize core_pressure -q -o "$tmp/ok.yaml"
  "$py" -c 'import h5py,sys; assert "ridge_height" not in h5py.File(sys.argv[1])["optimize/figures"]' \
    "$tmp/ok.h5" || fail "lanes figures in the history of a scene without lanes"
  ;;
*) fail "unknown command $cmd" ;;
esac
echo PASS

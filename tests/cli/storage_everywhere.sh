#!/usr/bin/env bash
# storage_everywhere.sh REELSIM STORAGE_SCENE: the storage stages a scene asks for are wound
# by compare, sweep and optimize too (docs/storage.md): compare's file holds each run's
# /storage as a run file does and its /summary the storage_* figures, equal to what `run`
# writes; sweep's figures gain storage_* (and a scene without stages keeps the columns it
# had); optimize constrains storage_max_core_pressure; --csv writes the stages; the CSV
# numbers are the shortest that read back.
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; scene="$2"; cases="$(dirname "$scene")"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
py=/usr/bin/python3; [ -x "$py" ] || py=python3
small=(--set winding.final_radius=0.1)

# run: the reference, with its stages as CSV
run "$bin" run "$scene" "${small[@]}" -o "$tmp/run.h5" --csv "$tmp/runcsv" -q
[ "$got" = 0 ] || fail "run: exit $got"
[ -f "$tmp/runcsv/pet-storage-storage.csv" ] || fail "run --csv wrote no storage CSV"
head -1 "$tmp/runcsv/pet-storage-storage.csv" | grep -q '^stage,hours,temperature_C,humidity_pct,core_pressure_Pa,layer,radius_m,sigma_r_Pa,sigma_theta_Pa,pressure_Pa$' \
  || fail "storage CSV header"
[ "$(sed -n 2p "$tmp/runcsv/pet-storage-wot.csv" | cut -d, -f2)" = 150 ] || fail "the web tension is not written 150"
grep -q 'e+0[0-9]' "$tmp/runcsv/pet-storage-wot.csv" && fail "exponent form of a whole number in the wot CSV"

# compare: the stages in the table, the file and the CSVs
run "$bin" compare "$scene" "$cases/newsprint-rider.yaml" "${small[@]}" -o "$tmp/cmp.h5" --csv "$tmp/cmpcsv"
[ "$got" = 0 ] || fail "compare: exit $got"
has 'after storage +hours +core P'
has 'risk in storage'
printf '%s\n' "$out" | grep -q 'winds the reel only' && fail "compare still says it winds the reel only"
[ -f "$tmp/cmpcsv/1-pet-storage-storage.csv" ] && [ -f "$tmp/cmpcsv/2-newsprint-rider-profile.csv" ] \
  || fail "compare --csv files: $(ls "$tmp/cmpcsv")"
[ -f "$tmp/cmpcsv/2-newsprint-rider-storage.csv" ] && fail "a storage CSV for a scene without stages"
cmp -s "$tmp/runcsv/pet-storage-storage.csv" "$tmp/cmpcsv/1-pet-storage-storage.csv" \
  || fail "compare's storage CSV differs from run's"

# sweep: storage_* figures for a scene with stages, none for one without
run "$bin" sweep "$scene" "${small[@]}" --vary winding.tension=100,150 -o "$tmp/sw.h5" --csv "$tmp/sw.csv"
[ "$got" = 0 ] || fail "sweep: exit $got"
printf '%s\n' "$out" | grep -q 'winds the reel only' && fail "sweep still says it winds the reel only"
head -1 "$tmp/sw.csv" | grep -q ',status,storage_core_pressure,storage_peak_pressure,storage_min_sigma_theta,storage_max_core_pressure,storage_max_peak_pressure,storage_starring_layers$' \
  || fail "sweep CSV header: $(head -1 "$tmp/sw.csv")"
run "$bin" sweep "$cases/newsprint-rider.yaml" "${small[@]}" --vary winding.tension=300,350 -o "$tmp/sw2.h5" --csv "$tmp/sw2.csv"
head -1 "$tmp/sw2.csv" | grep -q ',wall_seconds,status$' || fail "a scene without stages gained columns"

"$py" - "$tmp" <<'PY' || fail "the files"
import csv, sys, h5py, numpy as np
t = sys.argv[1]
run = h5py.File(t + "/run.h5", "r")
cmp = h5py.File(t + "/cmp.h5", "r")
g = cmp["runs/1-pet-storage"]
for k in ("hours", "core_pressure", "sigma_r", "sigma_theta"):
    assert np.array_equal(g["storage/" + k][()], run["storage/" + k][()]), k
assert "storage" not in cmp["runs/2-newsprint-rider"]
s = cmp["summary"]
cp = run["storage/core_pressure"][()]
assert s["storage_core_pressure"][0] == cp[-1], (s["storage_core_pressure"][0], cp)
assert s["storage_max_core_pressure"][0] == cp.max()
assert np.isnan(s["storage_core_pressure"][1])
assert s["storage_hours"][0] == run["storage/hours"][()][-1]
# the sweep's run at tension 150 is the run above (the scene's own tension)
rows = list(csv.DictReader(open(t + "/sw.csv")))
r150 = [r for r in rows if float(r["winding.tension"]) == 150][0]
assert float(r150["storage_core_pressure"]) == cp[-1], (r150["storage_core_pressure"], cp[-1])
assert float(r150["storage_max_core_pressure"]) == cp.max()
sr = run["storage/sigma_r"][()]
assert float(r150["storage_peak_pressure"]) == max(cp[-1], (-sr[-1]).max())
print("storage figures agree:", cp[-1], cp.max())
PY

# optimize: a storage figure as a constraint, in the table; values rounded; a fitting title
run "$bin" optimize "$scene" "${small[@]}" --vary winding.tension=80:200 --maximize winding.tension \
  --subject-to 'storage_max_core_pressure<=400e3' -o "$tmp/best.yaml"
[ "$got" = 0 ] || fail "optimize: exit $got"
has 'values rounded to 0.1 \(winding.tension\)'
has 'run phase +winding.tension +winding.tension +storage_max_core_pressure'
has 'storage_max_core_pressure +[0-9.e+]+ Pa'
printf '%s\n' "$out" | grep -E '^ +[0-9]+ (start|cobyla) ' | awk '{print $3}' | grep -Eqv '^[0-9]+(\.[0-9])?$' \
  && fail "a varied value with more than one decimal"
"$bin" check "$tmp/best.yaml" | head -1 | grep -q '^PET film stored for a week after winding, optimized: winding.tension=[0-9.]* for the greatest winding.tension$' \
  || fail "best.yaml title: $("$bin" check "$tmp/best.yaml" | head -1)"
"$py" - "$tmp/best.h5" <<'PY' || fail "optimize history"
import sys, h5py
f = h5py.File(sys.argv[1], "r")
c = f["optimize/figures/storage_max_core_pressure"][()]
b = int(f["optimize/best"][()])
assert c[b] <= 400e3, c[b]
v = f["optimize/values"][()][:, 0]
assert len(set(v)) == len(v), "a recipe wound twice"
PY
# without storage stages the storage figures are not in optimize's file
run "$bin" optimize "$cases/newsprint-rider.yaml" "${small[@]}" --vary winding.tension=200:400 \
  --minimize core_pressure -o "$tmp/best2.yaml" -q
"$py" -c 'import h5py,sys; assert "storage_core_pressure" not in h5py.File(sys.argv[1])["optimize/figures"]' \
  "$tmp/best2.h5" || fail "storage figures in the history of a scene without stages"
# a storage figure of a scene without stages is refused before anything is wound
run "$bin" optimize "$cases/newsprint-rider.yaml" "${small[@]}" --vary winding.tension=200:400 \
  --minimize core_pressure --subject-to 'storage_core_pressure<=1e6' -o "$tmp/best3.yaml"
[ "$got" = 2 ] || fail "storage figure without stages: exit $got"
has 'storage_core_pressure: .*newsprint-rider.yaml has no storage stages'
[ -e "$tmp/best3.h5" ] && fail "a refused optimize wrote its history"
echo PASS

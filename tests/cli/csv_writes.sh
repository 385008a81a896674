#!/usr/bin/env bash
# csv_writes.sh REELSIM SCENE [SUBDIR]: `run --csv DIR` writes DIR/<scene>-profile.csv and
# DIR/<scene>-wot.csv, a header and one row per layer, the numbers those of the HDF5
# file; the summary names them; nothing else is left in DIR. Without SUBDIR DIR exists
# beforehand; with it (e.g. made/csv) DIR and its parents are made, as mkdir -p does.
set -u
bin="$1"; scene="$2"; sub="${3:-}"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
csv="$tmp/csv"
if [ -n "$sub" ]; then csv="$tmp/$sub"; else mkdir "$csv"; fi
name="$(basename "$scene" .yaml)"
out="$("$bin" run "$scene" -o "$tmp/r.h5" --csv "$csv" 2>&1)" || { printf '%s\n' "$out"; fail "run failed"; }
printf '%s\n' "$out" | grep -Eq "csv +$csv/$name-\{profile,wot\}\.csv" || { printf '%s\n' "$out"; fail "summary does not name the CSV files"; }
p="$csv/$name-profile.csv"; w="$csv/$name-wot.csv"
[ -s "$p" ] && [ -s "$w" ] || fail "CSV files missing"
[ "$(head -n 1 "$p")" = "layer,radius_m,sigma_r_Pa,sigma_theta_Pa,pressure_Pa,wound_on_tension_N_per_m" ] || fail "profile header: $(head -n 1 "$p")"
[ "$(head -n 1 "$w")" = "radius_m,web_tension_N_per_m,nip_load_N_per_m,wound_on_tension_N_per_m" ] || fail "wot header: $(head -n 1 "$w")"
[ "$(wc -l < "$p")" -eq 201 ] && [ "$(wc -l < "$w")" -eq 201 ] || fail "expected 200 rows each"
# column 3 of the profile is /final/sigma_r: the same doubles (the CSV has the shortest
# digits that read back, h5dump 17); awk reads both with strtod
h5dump -d /final/sigma_r -m '%.17g' -y -w 0 -o "$tmp/s.txt" "$tmp/r.h5" >/dev/null
paste -d' ' <({ tr ',' '\n' < "$tmp/s.txt"; echo; } | sed 's/ //g; /^$/d') <(tail -n +2 "$p" | cut -d, -f3) |
  awk 'NF != 2 || $1 + 0 != $2 + 0 { bad = 1 } END { exit bad }' ||
  fail "profile sigma_r_Pa differs from /final/sigma_r"
[ "$(ls -A "$csv" | wc -l)" -eq 2 ] || { ls -la "$csv"; fail "stray files in the CSV directory"; }
echo PASS

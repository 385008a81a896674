#!/usr/bin/env bash
# history_csv.sh REELSIM SCENE: run --csv DIR exports the history stages when the scene
# records them (output.history_every): DIR/<scene>-history.csv, one row per wound layer per
# stage (stages at 50, 100, 150, 200 of 200 layers: 500 rows), and the last stage is the
# final profile, digit for digit; without a history no history file. The JSON summary
# lists it.
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
run "$bin" run "$scene" -o "$tmp/h.h5" --csv "$tmp/csv" --set output.history_every=50
[ "$got" -eq 0 ] || fail "run: exit $got"
has '^  csv +.*/csv/small-\{profile,wot,history\}\.csv$'
h="$tmp/csv/small-history.csv"
[ -f "$h" ] || fail "no history CSV"
[ "$(head -1 "$h")" = "stage,layers_wound,roll_radius_m,layer,radius_m,sigma_r_Pa,sigma_theta_Pa,pressure_Pa" ] ||
  fail "header: $(head -1 "$h")"
[ "$(tail -n +2 "$h" | wc -l)" -eq 500 ] || fail "expected 500 rows"
[ "$(tail -n +2 "$h" | cut -d, -f1,2 | sort -u | tr '\n' ' ')" = "1,50 2,100 3,150 4,200 " ] ||
  fail "stages: $(tail -n +2 "$h" | cut -d, -f1,2 | sort -u | tr '\n' ' ')"
# the last stage (layer, radius, sigma_r, sigma_theta) against the profile's columns
diff <(awk -F, '$1 == 4 {print $4 "," $5 "," $6 "," $7}' "$h") \
     <(tail -n +2 "$tmp/csv/small-profile.csv" | cut -d, -f1-4) >/dev/null ||
  fail "the last stage is not the final profile"
# no history recorded: no history file
run "$bin" run "$scene" -o "$tmp/n.h5" --csv "$tmp/plain"
[ "$got" -eq 0 ] || fail "run without history: exit $got"
[ ! -e "$tmp/plain/small-history.csv" ] || fail "a history CSV without a history"
[ -f "$tmp/plain/small-profile.csv" ] || fail "no profile CSV"
# --json lists the three files
"$bin" run "$scene" -o "$tmp/j.h5" --csv "$tmp/j" --set output.history_every=50 --json > "$tmp/j.json" ||
  fail "run --json"
python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); assert [p.rsplit("/",1)[1] for p in j["csv"]] == ["small-profile.csv","small-wot.csv","small-history.csv"], j["csv"]' "$tmp/j.json" ||
  fail "--json csv list"
echo PASS

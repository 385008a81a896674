#!/usr/bin/env bash
# storage_h5dump.sh REELSIM SCENE: a run of a scene with 3 storage stages writes /storage
# (docs/output.md): hours 0, 24, 36, 36.5 (cumulative), the stages' temperature and
# humidity (omitted values carried over), 4 x 200 stress arrays whose row 0 equals /final
# to 17 digits, the core pressure of stage 0 equal to /final's; a scene without storage
# writes no /storage group.
set -u
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
command -v h5dump >/dev/null || fail "h5dump not found (Debian package hdf5-tools)"

"$bin" run "$scene" -o "$tmp/s.h5" --quiet || fail "run failed"
vec() { h5dump -d "$1" -m '%.17g' -y -w 0 -o "$tmp/v.txt" "$tmp/s.h5" >/dev/null
        tr ',' '\n' < "$tmp/v.txt" | sed 's/ //g; /^$/d' | paste -sd, -; }
[ "$(vec /storage/hours)" = "0,24,36,36.5" ] || fail "/storage/hours is $(vec /storage/hours)"
[ "$(vec /storage/temperature)" = "23,40,40,23" ] || fail "/storage/temperature is $(vec /storage/temperature)"
[ "$(vec /storage/humidity)" = "50,50,80,50" ] || fail "/storage/humidity is $(vec /storage/humidity)"
h5dump -H -d /storage/sigma_r "$tmp/s.h5" | grep -q 'SIMPLE { ( 4, 200 )' || fail "/storage/sigma_r is not 4 x 200"
row() { h5dump -d "$1" -s "$2,0" -c "1,200" -m '%.17g' -y -w 0 -o "$tmp/row.txt" "$tmp/s.h5" >/dev/null
        tr ',' '\n' < "$tmp/row.txt" | sed 's/ //g; /^$/d'; }
col() { h5dump -d "$1" -m '%.17g' -y -w 0 -o "$tmp/col.txt" "$tmp/s.h5" >/dev/null
        tr ',' '\n' < "$tmp/col.txt" | sed 's/ //g; /^$/d'; }
for v in sigma_r sigma_theta; do
  diff <(row /storage/$v 0) <(col /final/$v) > /dev/null || fail "stage 0 of /storage/$v differs from /final/$v"
  if diff <(row /storage/$v 1) <(col /final/$v) > /dev/null; then fail "stage 1 of /storage/$v did not change"; fi
done
p0="$(vec /storage/core_pressure | cut -d, -f1)"
pf="$(h5dump -d /final/core_pressure -m '%.17g' -y -w 0 -o "$tmp/p.txt" "$tmp/s.h5" >/dev/null; tr -d ' \n' < "$tmp/p.txt")"
[ "$p0" = "$pf" ] || fail "stage 0 core pressure $p0, /final $pf"

sed '/^storage:/,/^output:/{/^output:/!d}' "$scene" > "$tmp/plain.yaml"
"$bin" run "$tmp/plain.yaml" -o "$tmp/n.h5" --quiet || fail "run without storage failed"
if h5ls "$tmp/n.h5" | grep -q '^storage'; then fail "a scene without storage wrote /storage"; fi
echo PASS

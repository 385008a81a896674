#!/usr/bin/env bash
# history_h5dump.sh REELSIM SCENE: `run --set output.history_every=50` on the 200-layer
# test reel writes /history as h5dump reads it: 4 stages at 50, 100, 150, 200 layers,
# 4 x 200 stress arrays (uncompressed, checksummed), NaN above each stage's outer radius, the last row equal to
# /final to 17 digits; history_every = 0 writes no /history group.
set -u
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
command -v h5dump >/dev/null || fail "h5dump not found (Debian package hdf5-tools)"

"$bin" run "$scene" --set output.history_every=50 -o "$tmp/h.h5" --quiet || fail "run failed"
h5dump -H -d /history/sigma_r "$tmp/h.h5" | grep -q 'DATASPACE  SIMPLE { ( 4, 200 ) / ( H5S_UNLIMITED, H5S_UNLIMITED ) }' ||
  { h5dump -H -d /history/sigma_r "$tmp/h.h5"; fail "/history/sigma_r is not 4 x 200, extendable"; }
# 4 x 200 values, under 1 MiB: stored as they are, checksummed (docs/output.md)
props="$(h5dump -H -d /history/sigma_r -p "$tmp/h.h5")"
grep -q 'CHECKSUM FLETCHER32' <<<"$props" || fail "/history/sigma_r carries no checksum"
if grep -q 'DEFLATE' <<<"$props"; then fail "/history/sigma_r (6.4 kB) is compressed"; fi
layers="$(h5dump -d /history/layers -y -w 0 -o "$tmp/layers.txt" "$tmp/h.h5" >/dev/null; tr -d ' \n' < "$tmp/layers.txt")"
echo "layers: $layers"
[ "$layers" = "50,100,150,200" ] || fail "/history/layers is '$layers'"

# one row of a 2-D dataset as numbers, one a line, 17 digits
row() { h5dump -d "$1" -s "$2,0" -c "1,200" -m '%.17g' -y -w 0 -o "$tmp/row.txt" "$tmp/h.h5" >/dev/null
        tr ',' '\n' < "$tmp/row.txt" | sed 's/ //g; /^$/d'; }
col() { h5dump -d "$1" -m '%.17g' -y -w 0 -o "$tmp/col.txt" "$tmp/h.h5" >/dev/null
        tr ',' '\n' < "$tmp/col.txt" | sed 's/ //g; /^$/d'; }
for v in sigma_r sigma_theta; do
  diff <(row /history/$v 3) <(col /final/$v) > /dev/null || fail "last stage of /history/$v differs from /final/$v"
  for s in 0 1 2; do
    k=$(( (s + 1) * 50 ))
    r="$(row /history/$v $s)"
    finite=$(printf '%s\n' "$r" | head -n $k | grep -civ 'nan')
    nans=$(printf '%s\n' "$r" | tail -n +$((k + 1)) | grep -ci '^nan$')
    [ "$finite" -eq "$k" ] && [ "$nans" -eq $((200 - k)) ] ||
      fail "stage $s of /history/$v: $finite finite of $k, $nans NaN of $((200 - k))"
  done
done

"$bin" run "$scene" -o "$tmp/n.h5" --quiet || fail "run without history failed"
if h5ls "$tmp/n.h5" | grep -q '^history'; then fail "history_every = 0 wrote /history"; fi
echo PASS

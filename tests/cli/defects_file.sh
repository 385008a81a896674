#!/usr/bin/env bash
# defects_file.sh REELSIM SCENE: the falling-taper scene's file records the hoop
# compression under /defects (verdict "present", the flagged range, the least hoop stress
# equal to the least of /final/sigma_theta), the starring rule beside it (verdict "ok",
# the compressed layers counted, a margin over 1), and stderr stays empty: it is no
# terminal, so no progress bar even though the run takes seconds.
set -u
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$bin" run "$scene" -o "$tmp/t.h5" > "$tmp/out" 2> "$tmp/err" || { cat "$tmp/out" "$tmp/err"; fail "run failed"; }
[ ! -s "$tmp/err" ] || { cat -A "$tmp/err" | head; fail "stderr is not empty (a progress bar on a non-terminal?)"; }
h5dump -a /defects/hoop_compression/verdict "$tmp/t.h5" | grep -q '"present"' || fail "hoop_compression verdict is not present"
h5dump -a /defects/starring/verdict "$tmp/t.h5" | grep -q '"ok"' || fail "starring verdict is not ok"
layers="$(h5dump -a /defects/hoop_compression/layers "$tmp/t.h5" | sed -n 's/.*(0): *//p')"
compressed="$(h5dump -a /defects/starring/compressed_layers "$tmp/t.h5" | sed -n 's/.*(0): *//p')"
margin="$(h5dump -a /defects/starring/min_margin -m '%.17g' "$tmp/t.h5" | sed -n 's/.*(0): *//p')"
echo "hoop compression in $layers layers, starring rule weighed $compressed, least margin $margin"
[ -n "$layers" ] && [ "$layers" = "$compressed" ] || fail "compressed_layers differs from hoop_compression/layers"
awk -v m="$margin" 'BEGIN { exit !(m > 1) }' || fail "min_margin $margin is not > 1"
h5dump -d /defects/starring/range_first_layer "$tmp/t.h5" > /dev/null || fail "no starring range datasets"
for v in pressure interlayer_slip core; do
  h5dump -a /defects/$v/verdict "$tmp/t.h5" | grep -q '"not assessed"' || fail "$v should be 'not assessed'"
done
h5dump -d /defects/hoop_compression/range_inner_radius "$tmp/t.h5" > /dev/null || fail "no range datasets"
least="$(h5dump -a /defects/hoop_compression/min_sigma_theta -m '%.17g' "$tmp/t.h5" | sed -n 's/.*(0): *//p')"
h5dump -d /final/sigma_theta -m '%.17g' -y -w 0 -o "$tmp/st.txt" "$tmp/t.h5" >/dev/null
want="$(tr ',' '\n' < "$tmp/st.txt" | sed 's/ //g; /^$/d' | sort -g | head -n 1)"
echo "min_sigma_theta $least, least of /final/sigma_theta $want"
[ -n "$least" ] && [ "$least" = "$want" ] || fail "min_sigma_theta differs from the least /final/sigma_theta"
echo PASS

#!/usr/bin/env bash
# air.sh REELSIM SCENE: `run` of a scene with `air` writes /layers/air_film and
# /layers/air_film_entrained (one value a layer, the film in the reel no thicker than as
# wound on), the summary's "entrained air" line and --json's "air" object; the same scene
# with air=null (no block) writes neither and has "air": null; plot draws <name>-air.png;
# compare of two speeds overlays the films and the spinning profiles.
set -u
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
command -v h5dump >/dev/null || fail "h5dump not found (Debian package hdf5-tools)"
"$bin" run "$scene" -o "$tmp/a.h5" > "$tmp/out.txt" || fail "run failed"
grep -q '^  entrained air  ' "$tmp/out.txt" || { cat "$tmp/out.txt"; fail "no 'entrained air' line"; }
# one dataset as numbers, one a line, 17 digits (its own scratch file: two run at once below)
col() { local o="$tmp/col-${1//\//_}.txt"
        h5dump -d "$1" -m '%.17g' -y -w 0 -o "$o" "$tmp/a.h5" >/dev/null
        tr ',' '\n' < "$o" | sed 's/ //g; /^$/d'; }
n=$(col /layers/radius | wc -l)
[ "$n" -gt 0 ] || fail "no layers"
[ "$(col /layers/air_film | wc -l)" -eq "$n" ] || fail "/layers/air_film is not one value a layer"
paste <(col /layers/air_film) <(col /layers/air_film_entrained) |
  awk '{ if (!($1 > 0 && $1 <= $2)) bad = 1 } END { exit bad }' ||
  fail "a film in the reel is not in (0, entrained]"
"$bin" run "$scene" -o "$tmp/j.h5" --json --quiet > "$tmp/j.json" || fail "run --json failed"
grep -q '"air":{"thickness":' "$tmp/j.json" || { cat "$tmp/j.json"; fail "no air object in --json"; }
"$bin" run "$scene" --set air=null -o "$tmp/n.h5" --json --quiet > "$tmp/n.json" || fail "air=null failed"
grep -q '"air":null' "$tmp/n.json" || fail "air=null is not \"air\": null"
if h5dump -H -d /layers/air_film "$tmp/n.h5" > /dev/null 2>&1; then fail "air=null wrote /layers/air_film"; fi
# plot: the air figure; compare of two speeds (with the centrifugal load): the runs' films
# overlaid and the spinning profiles beside the ones at rest
"$bin" plot "$tmp/a.h5" -o "$tmp/p" --quiet || fail "plot failed"
[ -s "$tmp/p/a-air.png" ] || { ls "$tmp/p"; fail "plot drew no a-air.png"; }
printf 'centrifugal: {}\n' > "$tmp/c.yaml"
cat "$scene" "$tmp/c.yaml" > "$tmp/s1.yaml"
sed 's/speed: 20/speed: 30/' "$tmp/s1.yaml" > "$tmp/s2.yaml"
grep -q 'speed: 30' "$tmp/s2.yaml" || fail "the scene's speed is not 20 m/s"
"$bin" compare "$tmp/s1.yaml" "$tmp/s2.yaml" -o "$tmp/cmp.h5" --quiet ||
  fail "compare failed"
h5dump -H -d /runs/2-s2/final_at_speed/sigma_r "$tmp/cmp.h5" > /dev/null 2>&1 ||
  { h5ls -r "$tmp/cmp.h5" | head -20; fail "compare has no /final_at_speed"; }
"$bin" plot "$tmp/cmp.h5" -o "$tmp/q" --quiet || fail "plot of the comparison failed"
[ -s "$tmp/q/cmp-air.png" ] && [ -s "$tmp/q/cmp-hoop.png" ] || { ls "$tmp/q"; fail "no cmp-air.png"; }
echo PASS

#!/usr/bin/env bash
# storage_plot.sh REELSIM SCENE: `reelsim plot` of a run with /storage draws
# <stem>-storage-pressure.png, -storage-hoop.png and -storage-core.png (whole PNGs); a run
# without storage draws none of them.
set -u
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
command -v gnuplot >/dev/null || fail "gnuplot not found (Debian package gnuplot-nox)"
"$bin" run "$scene" -o "$tmp/s.h5" --quiet || fail "run failed"
mkdir "$tmp/p" && "$bin" plot "$tmp/s.h5" -o "$tmp/p" || fail "plot failed"
for f in storage-pressure storage-hoop storage-core; do
  png="$tmp/p/s-$f.png"
  [ -s "$png" ] || fail "$png not written"
  [ "$(head -c 4 "$png" | tail -c 3)" = "PNG" ] || fail "$png is not a PNG"
done
sed '/^storage:/,/^output:/{/^output:/!d}' "$scene" > "$tmp/plain.yaml"
"$bin" run "$tmp/plain.yaml" -o "$tmp/n.h5" --quiet || fail "run without storage failed"
mkdir "$tmp/q" && "$bin" plot "$tmp/n.h5" -o "$tmp/q" || fail "plot without storage failed"
if ls "$tmp/q" | grep -q storage; then fail "a run without storage drew storage figures"; fi
echo PASS

#!/usr/bin/env bash
# lanes_plot.sh REELSIM SCENE SMALL: `reelsim plot` of a run with /lanes draws
# <stem>-lanes-pressure.png, -lanes-profile.png and -lanes-tension.png (whole PNGs); a run
# without lanes draws none of them.
set -u
bin="$1"; scene="$2"; small="$3"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
command -v gnuplot >/dev/null || fail "gnuplot not found (Debian package gnuplot-nox)"
"$bin" run "$scene" -o "$tmp/s.h5" --quiet || fail "run failed"
mkdir "$tmp/p" && "$bin" plot "$tmp/s.h5" -o "$tmp/p" || fail "plot failed"
for f in lanes-pressure lanes-profile lanes-tension; do
  png="$tmp/p/s-$f.png"
  [ -s "$png" ] || fail "$png not written"
  [ "$(head -c 4 "$png" | tail -c 3)" = "PNG" ] || fail "$png is not a PNG"
done
"$bin" run "$small" -o "$tmp/n.h5" --quiet || fail "run without lanes failed"
mkdir "$tmp/q" && "$bin" plot "$tmp/n.h5" -o "$tmp/q" || fail "plot without lanes failed"
if ls "$tmp/q" | grep -q lanes; then fail "a run without lanes drew lanes figures"; fi
echo PASS

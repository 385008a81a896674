#!/usr/bin/env bash
# plot_readable.sh REELSIM CASES: the figures an engineer shows (docs/cli.md, "reelsim
# plot"), read from the gnuplot scripts reelsim hands to gnuplot (a wrapper on PATH keeps
# them, then runs the real gnuplot): an air plot whose films the cut-off removed says so
# instead of drawing a 0 um line; the storage core pressure is drawn as steps with the
# temperature off the frame; pressures from 1000 kPa are drawn in MPa; legends sit below
# the frame; a compare plot draws the pressure limit; the optimize plot of a varied-key
# objective draws the evaluations.
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; cases="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
real="$(command -v gnuplot)" || fail "gnuplot not found (Debian package gnuplot-nox)"
mkdir "$tmp/bin" "$tmp/scripts"
cat > "$tmp/bin/gnuplot" <<WRAP
#!/usr/bin/env bash
for a in "\$@"; do [ -f "\$a" ] && cat "\$a" >> "$tmp/scripts/\$(basename "\$PWD").gp"; done
exec "$real" "\$@"
WRAP
chmod +x "$tmp/bin/gnuplot"
export PATH="$tmp/bin:$PATH"
plot() { # plot NAME FILE.h5: the scripts of `reelsim plot FILE` in $tmp/scripts/NAME.gp
  mkdir -p "$tmp/$1" && (cd "$tmp/$1" && "$bin" plot "$2" -o . -q) || fail "plot $2"
  gp="$tmp/scripts/$1.gp"; [ -s "$gp" ] || fail "no gnuplot script kept for $1"
}
small=(--set winding.final_radius=0.12)

"$bin" run "$cases/pet-topweb-air.yaml" --set air.cutoff=1000 --set winding.web_length=300 -o "$tmp/noair.h5" -q || fail "run noair"
plot noair "$tmp/noair.h5"
grep -q 'no air kept: every entrained film is below air.cutoff' "$gp" || fail "the empty air plot is not explained"
grep -q "set key below" "$gp" || fail "a run plot's legend is not below the frame"

"$bin" run "$cases/pet-storage.yaml" -o "$tmp/st.h5" -q || fail "run storage"
plot storage "$tmp/st.h5"
grep -q 'with fsteps linewidth 2.5' "$gp" || fail "the core pressure is not drawn as steps"
grep -q '^set y2range \[' "$gp" || fail "the temperature axis is not padded"

"$bin" run "$cases/newsprint-rider.yaml" --set winding.final_radius=0.2 -o "$tmp/rider.h5" -q || fail "run rider"
plot rider "$tmp/rider.h5"
grep -q "interlayer pressure P = −σr (MPa)" "$gp" || fail "1.3 MPa drawn in kPa"
"$bin" run "$cases/newsprint-taper.yaml" -o "$tmp/taper.h5" -q || fail "run taper"
plot taper "$tmp/taper.h5"
grep -q "interlayer pressure P = −σr (kPa)" "$gp" || fail "420 kPa not drawn in kPa"

"$bin" compare "$cases/newsprint-taper.yaml" "$cases/newsprint-falling-taper.yaml" \
  --set material.pressure_limit=6e5 -o "$tmp/cmp.h5" -q || fail "compare"
plot cmp "$tmp/cmp.h5"
grep -q "pressure limit 600 kPa" "$gp" || fail "the compare plot omits the pressure limit"

"$bin" optimize "$cases/pet-storage.yaml" --set winding.final_radius=0.1 --vary winding.tension=80:200 \
  --maximize winding.tension --subject-to 'core_pressure<=400e3' -o "$tmp/best.yaml" -q || fail "optimize"
plot opt "$tmp/best.h5"
grep -q "no evaluation of the objective" "$gp" && fail "the optimize plot of a varied key is empty"
grep -q "'feasible'" "$gp" || grep -q '"feasible"' "$gp" || fail "no feasible evaluations drawn"
echo PASS

#!/usr/bin/env bash
# reelsim sweep from the command line: sweep.sh CASE REELSIM SCENE [MPIRUN]
#   matches_runs  a 3 x 2 grid's figures equal the same runs made one by one with --set
#                 (reelsim run -o: /final/core_pressure; the peak pressure as the greatest of
#                 it and /final/pressure; the layers) to round-off (rel 1e-12)
#   grid_counts   a 4 x 3 x 2 grid: 24 runs, every combination once, first key slowest, the
#                 ends exact, the HDF5 file's shapes (parameters 3, values 24 x 3, figures 24)
#   lhs_strata    lhs:20 over two ranges and a list: 20 runs, each range's strata hit once
#                 each, every value inside [LO, HI], the list's items 5 times each, the same
#                 points again on a second run (the fixed seed)
#   failed_run    a run the solver cannot wind: status 3 and empty figures in its row, the
#                 other runs whole, exit 0, "1 failed"
#   profiles      --profiles adds /sweep/profiles/<i> with the runs' layers
#   plot          reelsim plot of a sweep: one PNG per figure (7), for one parameter (lines)
#                 and for two (a heat map); real PNGs, nothing else in the directory
#   interrupted   SIGTERM during a long sweep: exit 143, the message, no file and no temporary
#   mpi_same      mpirun -n 3 writes the same figures (all but wall_seconds) as one process
set -u
case_=$1 bin=$2 scene=$3 mpirun=${4:-}
. "$(dirname "$0")/../cli/lib.sh" # fail, run, has
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1

# close A B: |A - B| <= 1e-12 |B| (both numbers, as %.17g text)
close() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b;
                                           exit !(d <= 1e-12 * m) }'; }
# the scalar dataset PATH of FILE, %.17g
h5val() { h5dump -m %.17g -d "$2" "$1" | awk '/\(0\)/ { print $2; exit }'; }
# column NAME of CSV row I (1-based, after the header)
col() { awk -F, -v name="$2" -v row="$3" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i }
                                          NR == row + 1 { print $c }' "$1"; }

case $case_ in
matches_runs)
  run "$bin" sweep "$scene" --vary winding.tension=150:350:3 --vary core.radius=0.045,0.05 \
    --csv s.csv -o s.h5
  [ "$got" -eq 0 ] || fail "sweep failed"
  has "sweep: 6 runs on .* 0 failed"
  [ "$(wc -l <s.csv)" -eq 7 ] || fail "s.csv: not 6 rows"
  for i in 1 2 3 4 5 6; do
    t=$(col s.csv winding.tension $i) r=$(col s.csv core.radius $i)
    "$bin" run "$scene" --set winding.tension="$t" --set core.radius="$r" -o r$i.h5 -q ||
      fail "run $i failed"
    p=$(h5val r$i.h5 /final/core_pressure)
    close "$(col s.csv core_pressure $i)" "$p" || fail "run $i: core pressure $(col s.csv core_pressure $i) != $p"
    sr=$(h5dump -y -m %.17g -d /final/pressure r$i.h5 | sed -n '/DATA {/,/}/p' | tr -d ' ,' |
         grep -E '^-?[0-9]' | awk -v m="$p" '$1 > m { m = $1 } END { printf "%.17g", m }')
    close "$(col s.csv peak_pressure $i)" "$sr" || fail "run $i: peak pressure differs ($sr)"
    n=$(h5dump -d /final/radius r$i.h5 | grep -o 'DATASPACE  SIMPLE { ( [0-9]*' | grep -o '[0-9]*$')
    [ "$(col s.csv layers $i)" = "$n" ] || fail "run $i: $n layers"
    echo "run $i: tension $t, core radius $r: core pressure $p, $n layers: same"
  done ;;
grid_counts)
  run "$bin" sweep "$scene" --vary winding.tension=100:400:4 --vary core.radius=0.04:0.05:3 \
    --vary numerics.load_placement=beneath,hakiel --csv g.csv -o g.h5 -q
  [ "$got" -eq 0 ] || fail "sweep failed"
  [ "$(wc -l <g.csv)" -eq 25 ] || fail "not 24 runs"
  [ "$(cut -d, -f1-3 g.csv | sort -u | wc -l)" -eq 25 ] || fail "a combination is repeated"
  [ "$(col g.csv winding.tension 1)" = 100 ] && [ "$(col g.csv winding.tension 24)" = 400 ] ||
    fail "the tension's ends are not exact"
  [ "$(col g.csv core.radius 1)" = 0.04 ] || fail "LO of core.radius"
  [ "$(col g.csv core.radius 5)" = 0.05 ] || fail "HI of core.radius"
  [ "$(col g.csv winding.tension 6)" = 100 ] && [ "$(col g.csv winding.tension 7)" = 200 ] ||
    fail "the first key does not vary slowest"
  [ "$(col g.csv numerics.load_placement 2)" = hakiel ] || fail "the words"
  h5dump -H g.h5 >h.txt
  grep -A8 'DATASET "parameters"' h.txt | grep -q 'SIMPLE { ( 3 )' || fail "/sweep/parameters is not 3"
  grep -A2 'DATASET "values"' h.txt | grep -q 'SIMPLE { ( 24, 3 )' || fail "/sweep/values is not 24 x 3"
  for f in core_pressure peak_pressure min_sigma_theta final_radius layers wall_seconds status; do
    grep -A2 "DATASET \"$f\"" h.txt | grep -q 'SIMPLE { ( 24 )' || fail "/sweep/figures/$f"
  done
  h5dump -a '/sweep/values/words:numerics.load_placement' g.h5 | grep -q '"beneath,hakiel"' ||
    fail "the words attribute"
  echo "24 runs, every combination once" ;;
lhs_strata)
  run "$bin" sweep "$scene" --vary winding.tension=100:400 --vary core.radius=0.04:0.05:7 \
    --vary numerics.load_placement=beneath,hakiel --sample lhs:20 --csv l.csv -o l.h5 -q
  [ "$got" -eq 0 ] || fail "sweep failed"
  [ "$(wc -l <l.csv)" -eq 21 ] || fail "not 20 runs"
  for spec in "winding.tension 100 400" "core.radius 0.04 0.05"; do
    set -- $spec
    awk -F, -v name="$1" -v lo="$2" -v hi="$3" -v r=20 '
      NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i; next }
      { x = $c; if (x < lo || x > hi) { print name " = " x " outside"; bad = 1 }
        s = int((x - lo) / (hi - lo) * r); if (s == r) s = r - 1; hit[s]++ }
      END { for (s = 0; s < r; ++s) if (hit[s] != 1) { print name ": stratum " s " hit " hit[s] + 0 " times"; bad = 1 }
            exit bad }' l.csv || fail "$1 is not one sample per stratum"
  done
  [ "$(cut -d, -f3 l.csv | grep -c '^beneath$')" -eq 10 ] || fail "the list's items are not even"
  "$bin" sweep "$scene" --vary winding.tension=100:400 --vary core.radius=0.04:0.05:7 \
    --vary numerics.load_placement=beneath,hakiel --sample lhs:20 --csv l2.csv -o l2.h5 -q
  cmp <(cut -d, -f1-3 l.csv) <(cut -d, -f1-3 l2.csv) || fail "another run drew other points"
  echo "20 samples, one per stratum" ;;
failed_run)
  run "$bin" sweep "$scene" --vary numerics.max_steps=1,5000 --csv f.csv -o f.h5
  [ "$got" -eq 0 ] || fail "a failed run sank the sweep"
  has "sweep: 2 runs on .*, 1 failed"
  has "sweep: run 1 failed: .*CVODE needed more than 1 steps"
  [ "$(col f.csv status 1)" = 3 ] && [ "$(col f.csv status 2)" = 0 ] || fail "statuses"
  [ -z "$(col f.csv core_pressure 1)" ] || fail "a failed run has a core pressure"
  [ -n "$(col f.csv core_pressure 2)" ] || fail "the good run lacks its core pressure"
  h5dump -d /sweep/figures/core_pressure f.h5 | grep -qi nan || fail "no NaN in the file" ;;
profiles)
  run "$bin" sweep "$scene" --vary core.radius=0.04,0.05 --profiles -o p.h5 -q
  [ "$got" -eq 0 ] || fail "sweep failed"
  h5ls -r p.h5 >ls.txt
  cat ls.txt
  grep -q '^/sweep/profiles/0/sigma_theta *Dataset {300}' ls.txt || fail "run 0's profile"
  grep -q '^/sweep/profiles/1/radius *Dataset {200}' ls.txt || fail "run 1's profile" ;;
mpi_same)
  [ -n "$mpirun" ] || fail "no mpirun given"
  args=(sweep "$scene" --vary winding.tension=100:400:4 --vary core.radius=0.04,0.045,0.05
        --vary numerics.max_steps=1,5000 --profiles)
  run "$bin" "${args[@]}" --csv one.csv -o one.h5 --threads 1
  [ "$got" -eq 0 ] || fail "one process failed"
  run "$mpirun" --allow-run-as-root --oversubscribe -n 3 "$bin" "${args[@]}" --csv three.csv -o three.h5
  [ "$got" -eq 0 ] || fail "3 ranks failed"
  has "sweep: 24 runs on 2 MPI ranks"
  # every column but wall_seconds, digit for digit
  w=$(head -1 one.csv | tr , '\n' | grep -n '^wall_seconds$' | cut -d: -f1)
  cmp <(cut -d, -f"$w" --complement one.csv) <(cut -d, -f"$w" --complement three.csv) ||
    fail "the figures differ"
  for f in core_pressure peak_pressure min_sigma_theta final_radius layers starring_layers slip_margin status; do
    cmp <(h5dump -d /sweep/figures/$f -m %.17g one.h5 | sed 1d) \
        <(h5dump -d /sweep/figures/$f -m %.17g three.h5 | sed 1d) || fail "/sweep/figures/$f differs"
  done
  cmp <(h5dump -g /sweep/profiles one.h5 | sed 1d) <(h5dump -g /sweep/profiles three.h5 | sed 1d) ||
    fail "the profiles differ"
  echo "3 ranks: the same figures and profiles as 1 process" ;;
plot)
  figs="core_pressure peak_pressure min_sigma_theta final_radius layers starring_layers wall_seconds"
  # slip_margin is NaN in every run (no material.friction_layer): not drawn
  "$bin" sweep "$scene" --vary winding.tension=100:400:4 -o one.h5 -q || fail "sweep 1"
  "$bin" sweep "$scene" --vary winding.tension=100:400:3 --vary numerics.load_placement=beneath,hakiel \
    -o two.h5 -q || fail "sweep 2"
  for f in one two; do
    mkdir png-$f
    run "$bin" plot $f.h5 -o png-$f
    [ "$got" -eq 0 ] || fail "plot $f.h5"
    for g in $figs; do
      has "^png-$f/$f-$g\.png$"
      is_png "png-$f/$f-$g.png"
    done
    [ "$(ls -A png-$f | wc -l)" -eq 7 ] || { ls -la png-$f; fail "not 7 files"; }
  done ;;
interrupted)
  "$bin" sweep "$scene" --set winding.final_radius=0.5 --vary winding.tension=100:400:400 \
    -o int.h5 >log.txt 2>&1 &
  pid=$!
  for _ in $(seq 100); do grep -q "^sweep: 400 runs" log.txt && break; sleep 0.1; done
  sleep 0.5
  kill -TERM "$pid"
  wait "$pid"
  got=$?
  cat log.txt
  [ "$got" -eq 143 ] || fail "exit $got, expected 143"
  grep -q "reelsim: sweep: terminated (SIGTERM) (no output written)" log.txt || fail "message"
  [ -z "$(ls -A | grep -v '^log.txt$')" ] || { ls -la; fail "files were left"; } ;;
*) fail "unknown case $case_" ;;
esac
echo PASS

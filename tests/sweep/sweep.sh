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
#   plan_interrupted  SIGINT while a --sample lhs:10000000 plan is made and checked (it would
#                 take minutes): exit 130 within 5 s (measured: 0.1-0.5 s), the message, no file
#   grid_terminated   SIGTERM while a 10^6 x 10 grid is checked: exit 143, no file
# Under mpirun -n 3, each rank in its own folder node<R> (a node's own disk), as a wrapper
# script arranges from OMPI_COMM_WORLD_RANK:
#   mpi_rank_fails    rank 1's folder lacks the model: exit 2, rank 0 prints "rank 1: ...no
#                 material model 'myweb'..." once, nothing wound, no file; the same with
#                 lhs:10^7, where ranks 0 and 2 stop checking when told (within 60 s, not
#                 the minutes 10^7 checks take)
#   mpi_scene_differs rank 1's model has another E_theta: exit 2 naming rank 1 and the digests;
#                 the same model found in another folder on each rank is accepted
#   mpi_signal_worker SIGTERM to rank 1's process mid-sweep: exit 143, "terminated (SIGTERM)
#                 on rank 1 (no output written)", every rank gone within 10 s, no file
#   mpi_signal_root   SIGINT to rank 0 mid-sweep: exit 130, "interrupted", no file
#   mpi_signal_checking SIGHUP to rank 2 while the ranks check lhs:10^7: exit 129, "on rank 2
#                 before winding", every rank gone within 10 s
#   mpi_run_failed    runs that fail on a worker rank: their messages printed by rank 0, exit 0
#   mpi_grid_1e12     a 10^12-run grid refused (exit 2) before any scene is loaded, said once
#   mpi_module    a copy of the program without its MPI module (reelsim-mpi.so beside it)
#                 under mpirun -n 1: says the module does not load, winds as one process
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
# handles PID SIG: waits (at most 30 s) until process PID has its handler for SIG (its
# SigCgt mask in /proc), so that a signal sent then is reelsim's to handle
handles() {
  local bit n
  n=$(kill -l "$2")
  for _ in $(seq 600); do
    bit=$(awk -v n="$n" '/^SigCgt:/ { v = 0; h = substr($2, length($2) - 3) # signals 1-16
            for (i = 1; i <= length(h); ++i) v = v * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1
            print int(v / 2 ^ (n - 1)) % 2 }' /proc/"$1"/status 2>/dev/null)
    [ "$bit" = 1 ] && return 0
    sleep 0.05
  done
  fail "process $1 never handled SIG$2"
}
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
  export TMPDIR=$tmp # Open MPI's session folder: see mpi_* below
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
mpi_module)
  [ -n "$mpirun" ] || fail "no mpirun given"
  export TMPDIR=$tmp
  mkdir bin && cp "$bin" bin/reelsim
  run "$mpirun" --allow-run-as-root --oversubscribe -n 1 bin/reelsim sweep "$scene" \
      --vary winding.tension=100:400:2 -o one.h5
  [ "$got" -eq 0 ] || fail "exit $got, expected 0"
  has "^reelsim: sweep: started by mpirun, but its MPI module does not load \(.*/reelsim-mpi\.so.*\): running as one process$"
  has "^sweep: 2 runs on [0-9]+ threads? in "
  [ -s one.h5 ] || fail "no file" ;;
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
plan_interrupted | grid_terminated)
  if [ "$case_" = plan_interrupted ]; then
    sig=INT want=130 word=interrupted vary=(--vary winding.tension=100:400 --sample lhs:10000000)
  else
    sig=TERM want=143 word='terminated \(SIGTERM\)'
    vary=(--vary winding.tension=100:400:1000000 --vary core.radius=0.04:0.05:10)
  fi
  # SIGINT reaches reelsim as Ctrl-C would even where the shell ignores it in background jobs
  env --default-signal=INT "$bin" sweep "$scene" "${vary[@]}" -o big.h5 >log.txt 2>&1 &
  pid=$!
  handles "$pid" "$sig"
  sleep 1
  t0=$(date +%s.%N)
  kill -"$sig" "$pid"
  wait "$pid"
  got=$?
  took=$(echo "$(date +%s.%N) - $t0" | bc)
  cat log.txt
  echo "stopped $took s after SIG$sig"
  [ "$got" -eq "$want" ] || fail "exit $got, expected $want"
  grep -Eq "reelsim: sweep: $word before winding \(no output written\)" log.txt || fail "message"
  [ "$(echo "$took < 5" | bc)" -eq 1 ] || fail "took $took s to stop"
  [ -z "$(ls -A | grep -v '^log.txt$')" ] || { ls -la; fail "files were left"; } ;;
mpi_*)
  [ -n "$mpirun" ] || fail "no mpirun given"
  # Open MPI's session folder in our own TMPDIR: two mpiruns starting at once in /tmp race
  # for /tmp/ompi.<host>.<uid> ("mkdir ... File exists", orte_init fails)
  export TMPDIR=$tmp
  # node0: the scene and its model (material: myweb, found beside the scene)
  mkdir node0 node1 node2
  sed -e '/^  name: test-web$/d' -e '/^  caliper:/d' -e '/^  E_theta:/d' -e '/^  radial:/d' \
      -e 's/^material:$/material: {model: myweb}/' "$scene" >node0/scene.yaml
  printf 'name: test-web\ncaliper: 100.0e-6\nE_theta: 4.0e9\nradial: {law: linear, E_r: 20.0e6}\n' \
    >node0/myweb.yaml
  for n in 1 2; do cp node0/scene.yaml node0/myweb.yaml node$n/; done
  # a rank in its own folder (its node's disk), its pid in pid.<rank> (exec keeps the pid)
  printf '%s\n' '#!/bin/bash' 'd=$(cd "$(dirname "$0")" && pwd) r=${OMPI_COMM_WORLD_RANK:-0}' \
    'echo $$ >"$d/pid.$r"' 'cd "$d/node$r" && exec "$@"' >wrap.sh
  chmod +x wrap.sh
  mpi() { env --default-signal=INT "$mpirun" --allow-run-as-root --oversubscribe -n 3 ./wrap.sh "$bin" "$@"; }
  # every rank's process gone (or a zombie not yet reaped by mpirun) within LIMIT s of T0
  all_gone() {
    local p st alive
    for _ in $(seq 500); do
      alive=0
      for p in $(cat pid.0 pid.1 pid.2); do
        st=$(awk '{ print $3 }' /proc/"$p"/stat 2>/dev/null)
        [ -n "$st" ] && [ "$st" != Z ] && alive=1
      done
      [ "$alive" -eq 0 ] && break
      sleep 0.02
    done
    took=$(echo "$(date +%s.%N) - $1" | bc)
    echo "every rank stopped $took s after the signal"
    [ "$(echo "$took < $2" | bc)" -eq 1 ] || fail "the ranks took $took s to stop"
  }
  # signal_rank SIGNAL RANK STATUS ARGS...: the signal to a rank's process once the winding
  # (with --sample lhs: the checking) is under way
  signal_rank() {
    local sig=$1 r=$2 want=$3 m t0
    shift 3
    mpi sweep scene.yaml "$@" -o "$PWD/out.h5" >log.txt 2>&1 &
    m=$!
    for _ in $(seq 300); do [ -s pid.0 ] && [ -s pid.1 ] && [ -s pid.2 ] && break; sleep 0.1; done
    case "$*" in
    *lhs*) # until the rank handles the signal (MPI's start-up done; under load it takes
           # seconds), then into its checks
      handles "$(cat pid."$r")" "$sig"
      sleep 1 ;;
    *) for _ in $(seq 300); do grep -q "^sweep: .* runs of" log.txt && break; sleep 0.1; done
       sleep 1 ;;
    esac
    t0=$(date +%s.%N)
    kill -"$sig" "$(cat pid."$r")"
    all_gone "$t0" 10
    wait "$m"
    got=$?
    cat log.txt
    [ "$got" -eq "$want" ] || fail "exit $got, expected $want"
    [ -z "$(ls | grep '^out\.h5')" ] || { ls -la; fail "an output file was left"; }
  }
  # long enough that the signal, a second into the winding, finds it under way (40 runs of
  # this scene take about a second on a free machine)
  long=(--set winding.final_radius=1 --set numerics.rtol=1e-6 --vary winding.tension=100:400:400)
  case $case_ in
  mpi_rank_fails)
    rm node1/myweb.yaml
    run mpi sweep scene.yaml --vary winding.tension=100:300:5 -o "$PWD/out.h5"
    [ "$got" -eq 2 ] || fail "exit $got, expected 2"
    has "^reelsim: rank 1: scene\.yaml:[0-9]+: material\.model: no material model 'myweb'"
    has "^reelsim: sweep: nothing was wound$"
    [ "$(printf '%s\n' "$out" | grep -c "no material model")" -eq 1 ] || fail "said more than once"
    t0=$(date +%s.%N)
    run mpi sweep scene.yaml --vary winding.tension=100:300 --sample lhs:10000000 -o "$PWD/out.h5"
    took=$(echo "$(date +%s.%N) - $t0" | bc)
    echo "lhs:10^7 with rank 1 failing: $took s"
    [ "$got" -eq 2 ] || fail "exit $got, expected 2"
    has "^reelsim: rank 1: scene\.yaml:[0-9]+: material\.model: no material model 'myweb'"
    # checking 10^7 runs takes each rank minutes; told, they stop at once (5-16 s in all
    # here, mpirun's start and end included, with other tests' ranks on the 2 cores)
    [ "$(echo "$took < 60" | bc)" -eq 1 ] || fail "the other ranks went on checking ($took s)"
    [ ! -e out.h5 ] || fail "a file was written" ;;
  mpi_scene_differs)
    sed -i 's/4.0e9/4.5e9/' node1/myweb.yaml
    run mpi sweep scene.yaml --vary winding.tension=100:300:5 -o "$PWD/out.h5"
    [ "$got" -eq 2 ] || fail "exit $got, expected 2"
    has "^reelsim: sweep: rank 1 resolved other scenes than rank 0 \(digest [0-9a-f]{16} against [0-9a-f]{16}\): every rank must read the same scene and model files$"
    printf '%s\n' "$out" | grep -q "rank 2 resolved" && fail "rank 2 holds the same scene"
    [ ! -e out.h5 ] || fail "a file was written"
    # where a model was found (node<R>/myweb.yaml) is not part of the digest
    sed -i 's/4.5e9/4.0e9/' node1/myweb.yaml
    run mpi sweep scene.yaml --vary winding.tension=100:300:5 -o "$PWD/out.h5" -q
    [ "$got" -eq 0 ] || fail "the same model in other folders was refused" ;;
  mpi_signal_worker)
    signal_rank TERM 1 143 "${long[@]}"
    grep -q "^reelsim: sweep: terminated (SIGTERM) on rank 1 (no output written)$" log.txt ||
      fail "message" ;;
  mpi_signal_root)
    signal_rank INT 0 130 "${long[@]}"
    grep -q "^reelsim: sweep: interrupted (no output written)$" log.txt || fail "message" ;;
  mpi_signal_checking)
    signal_rank HUP 2 129 --vary winding.tension=100:400 --sample lhs:10000000
    grep -q "^reelsim: sweep: terminated (SIGHUP) on rank 2 before winding (no output written)$" \
      log.txt || fail "message" ;;
  mpi_run_failed)
    run mpi sweep scene.yaml --vary numerics.max_steps=1,5000,1 --csv f.csv -o "$PWD/f.h5"
    [ "$got" -eq 0 ] || fail "a failed run sank the sweep"
    has "^reelsim: sweep: run 1 failed: .*CVODE needed more than 1 steps"
    has "^reelsim: sweep: run 3 failed: .*CVODE needed more than 1 steps"
    has "sweep: 3 runs on 2 MPI ranks .*, 2 failed" ;;
  mpi_grid_1e12)
    run mpi sweep scene.yaml --vary winding.tension=100:200:1000000 \
      --vary core.radius=0.04:0.05:1000000 -o "$PWD/out.h5"
    [ "$got" -eq 2 ] || fail "exit $got, expected 2"
    [ "$(printf '%s\n' "$out" | grep -c "^reelsim: --vary: the grid has more than 10000000 runs$")" -eq 1 ] ||
      fail "not said once" ;;
  *) fail "unknown case $case_" ;;
  esac ;;
*) fail "unknown case $case_" ;;
esac
echo PASS

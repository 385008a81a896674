#!/usr/bin/env bash
# study.sh REELSIM SCENES CASE: `reelsim study` end to end (docs/accuracy.md).
#   small_quick  no nip (small.yaml): the study completes, writes study.h5, study.csv and
#                study.png; the checks below on its CSV
#   nip_quick    a 120-layer reel with the contact nip (study-nip.yaml): the same, and the nip
#                knobs are there (none of them in small_quick)
#   bad_input    a bad --set: exit 2, nothing wound, no directory made
#   not_dir      -o onto a file, or below one: exit 2 before anything is wound
#   usage        no scene: exit 2
# Checks on a finished study's CSV:
#   - the reference is tighter than every other run: each run (but the second reference,
#     tighter on purpose) is coarser or equal in every knob: rtol, layers per step, update
#     interval no smaller; nodes and terms no larger; the reference solves the nip at every
#     layer (update_every 1), which every policy is coarser than;
#   - the second, tighter reference differs from the reference by less than the smallest
#     error any other run reports (tightening further would not change the picture);
#   - errors fall monotonically along each knob within noise: ordered from the finest level
#     to the coarsest (the default run at its level included), the largest error of a
#     coarser level is never below 0.5 x that of the finer one minus 10 x the reference's
#     uncertainty (CVODE's error is not strictly monotone in rtol, and levels whose error is
#     set by the other knobs differ only by noise);
#   - the history runs give the default's answer bit for bit; every run has a time > 0.
set -u
bin="$1"; sc="$2"; case="$3"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib.sh" # fail, run, has, is_png
export TMPDIR="$tmp"

# awk over the CSV with columns by name: c["rtol"] is the rtol column's index
csv_awk() {
  awk -F, -v prog="$1" '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { n++; for (i = 1; i <= NF; ++i) v[n, i] = $i; gsub(/"/, "", v[n, c["knob"]]) }
    END {
      ref = 0; ref2 = 0; def = 0
      for (r = 1; r <= n; ++r) {
        k = v[r, c["knob"]]
        if (k == "reference") ref = r; else if (k == "reference2") ref2 = r; else if (k == "default") def = r
      }
      if (!ref || !ref2 || !def) { print "FAIL: no reference, reference2 or default row"; exit 1 }
      bad = 0
      # 1. coarser or equal than the reference
      for (r = 1; r <= n; ++r) {
        if (r == ref || r == ref2) continue
        if (v[r, c["rtol"]] + 0 < v[ref, c["rtol"]] + 0 ||
            v[r, c["layers_per_step"]] + 0 < v[ref, c["layers_per_step"]] + 0 ||
            v[r, c["nodes"]] + 0 > v[ref, c["nodes"]] + 0 ||
            v[r, c["terms"]] + 0 > v[ref, c["terms"]] + 0) {
          print "FAIL: run " r " (" v[r, c["label"]] ") is finer than the reference"; bad = 1
        }
        ue = v[ref, c["update_every"]] + 0
        if (ue > 1 && !(v[r, c["update_every"]] + 0 >= ue)) {
          print "FAIL: run " r " updates the nip more often than the reference"; bad = 1
        }
        if (v[r, c["wall_seconds"]] + 0 <= 0 || v[r, c["cpu_seconds"]] + 0 <= 0) {
          print "FAIL: run " r " has no time"; bad = 1
        }
        if (v[r, c["knob"]] == "history_every" && v[r, c["identical_to_default"]] + 0 != 1) {
          print "FAIL: history run " r " does not give the default answer"; bad = 1
        }
      }
      if (v[ref, c["update_every"]] != "" && c["update_every"] && prog == "nip" &&
          v[ref, c["update_every"]] + 0 != 1) { print "FAIL: the reference does not solve the nip at every layer"; bad = 1 }
      # 2. tightening the reference further changes the answer less than the smallest
      #    error reported (the criterion of the issue): err_max of reference2 below every other
      #    run err_max. (With the contact nip, T0 converges at first order in M because of
      #    its stick/slip kinks, so the references do not agree to round-off.)
      u = v[ref2, c["err_max"]] + 0
      smallest = -1
      for (r = 1; r <= n; ++r) {
        if (r == ref || r == ref2) continue
        e = v[r, c["err_max"]] + 0
        if (smallest < 0 || e < smallest) smallest = e
      }
      printf "reference uncertainty (err_max of reference2): %g, smallest error reported: %g\n", u, smallest
      if (!(u < smallest)) { print "FAIL: the reference is not tighter than the smallest error (" u " >= " smallest ")"; bad = 1 }
      # 3. monotone along each knob, within noise
      split("rtol layers_per_step nodes terms T0_rtol update_every", knobs, " ")
      for (q = 1; q <= 6; ++q) {
        K = knobs[q]; m = 0
        for (r = 1; r <= n; ++r) {
          isdef = (r == def && K != "update_every")
          if (v[r, c["knob"]] != K && !isdef) continue
          x = v[r, c[K]] + 0
          if (K == "nodes" || K == "terms") x = (x > 0 ? 1 / x : 0) # fewer is coarser
          if (K == "layers_per_step") x = x - 1
          m++; xs[m] = x; es[m] = v[r, c["err_max"]] + 0; ls[m] = v[r, c["label"]]
        }
        if (m < 2) continue
        for (i = 1; i <= m; ++i) for (j = i + 1; j <= m; ++j) if (xs[j] < xs[i]) {
          t = xs[i]; xs[i] = xs[j]; xs[j] = t; t = es[i]; es[i] = es[j]; es[j] = t
          t = ls[i]; ls[i] = ls[j]; ls[j] = t }
        line = K ":"
        for (i = 1; i <= m; ++i) line = line " " ls[i] "=" es[i]
        print line
        for (i = 2; i <= m; ++i)
          if (es[i] < 0.5 * es[i - 1] - 10 * u) {
            print "FAIL: " K ": error falls from " es[i - 1] " (" ls[i - 1] ") to " es[i] " (" ls[i] ")"; bad = 1
          }
      }
      print "runs: " n
      exit bad
    }' "$2"
}

check_study() { # dir kind
  for f in study.h5 study.csv study.png; do [ -s "$1/$f" ] || fail "no $1/$f"; done
  is_png "$1/study.png"
  h5dump -H "$1/study.h5" > "$tmp/h5.txt" || fail "h5dump cannot read study.h5"
  for d in label knob rtol layers_per_step wall_seconds cpu_seconds err_core_pressure \
           err_peak_pressure err_sigma_r err_sigma_theta err_T0_final err_max on_front; do
    grep -q "DATASET \"$d\"" "$tmp/h5.txt" || fail "study.h5 lacks /study/runs/$d"
  done
  rows=$(($(wc -l < "$1/study.csv") - 1))
  has "[0-9]+ layers: $rows runs \(quick\)"
  csv_awk "$2" "$1/study.csv" || fail "CSV checks"
  [ -z "$(ls -A "$tmp" | grep -v -e '^out$' -e '^h5.txt$')" ] || { ls -la "$tmp"; fail "stray files"; }
}

case "$case" in
small_quick) # into a directory made as mkdir -p would
  run "$bin" study "$sc/small.yaml" --quick -o "$tmp/out/a/b"
  [ "$got" -eq 0 ] || fail "exit status $got, expected 0"
  has "^reference: +rtol 1e-09, 1 layer per step$"
  has "reference uncertainty"
  has "^defaults: core pressure error"
  has "^Pareto front \([0-9]+ runs\)"
  has "answers are bit for bit those of the defaults"
  printf '%s\n' "$out" | grep -q "nip" && fail "a scene without a nip got nip runs"
  check_study "$tmp/out/a/b" plain
  ;;
nip_quick)
  run "$bin" study "$sc/study-nip.yaml" --quick -o "$tmp/out"
  [ "$got" -eq 0 ] || fail "exit status $got, expected 0"
  has "^reference: +rtol 1e-09, 1 layer per step, nip 128 nodes, 512 terms, nip every 1 layer$"
  for k in nodes=32 terms=16 T0_rtol=0.01 update_every=10; do has "^$k "; done
  check_study "$tmp/out" nip
  ;;
bad_input)
  run "$bin" study "$sc/small.yaml" --quick -o "$tmp/out" --set numerics.rtol=abc
  [ "$got" -eq 2 ] || fail "exit status $got, expected 2"
  has "--set numerics\.rtol=abc: not a number"
  [ ! -e "$tmp/out" ] || fail "a directory was made"
  ;;
not_dir)
  touch "$tmp/file"
  for d in "$tmp/file" "$tmp/file/sub"; do
    run "$bin" study "$sc/small.yaml" --quick -o "$d"
    [ "$got" -eq 2 ] || fail "exit status $got, expected 2"
    has "reelsim: study: output directory '$d'.* is not a directory"
    printf '%s\n' "$out" | grep -q "reference" && fail "something was wound"
  done
  [ "$(ls -A "$tmp")" = file ] || { ls -la "$tmp"; fail "stray files"; }
  ;;
usage)
  run "$bin" study
  [ "$got" -eq 2 ] || fail "exit status $got, expected 2"
  has "study: missing the scene file"
  run "$bin" study "$sc/small.yaml" --jobs 0
  [ "$got" -eq 2 ] || fail "exit status $got, expected 2"
  ;;
*) fail "unknown case $case" ;;
esac
echo ok

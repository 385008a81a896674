#!/usr/bin/env bash
# atomic_symlink.sh REELSIM SCENE CASE: every output goes through the atomic writer
# (issue 36): temporaries created O_EXCL | O_NOFOLLOW, so symlinks planted under the
# temporary names the next processes would use redirect nothing; stale temporaries of
# this program are removed.
#   optimize  optimize -o best.yaml (its scene and its history best.h5) with symlinks
#             planted for the next 300 pids, in both the old (.tmp-PID) and the new
#             (.tmp.PID.N) pattern: the victim file is unchanged, the outputs are regular
#   run       the same for run -o out.h5 (and its --csv files)
#   sweep     the same for sweep -o sweep.h5
#   stale     out.h5.tmp.PID.N of a pid that is not alive and 1 h old is removed by the
#             next write of out.h5; a fresh one, a live pid's and another file's are kept
set -u
bin="$1"; scene="$2"; case="$3"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib.sh" # fail, run, has
cd "$tmp" || fail "cd"
echo "precious" > victim
plant() { # NAME...: symlinks to the victim under every temporary name of the next pids
  # (one process plants them all, so the pids it would use up are not its own)
  python3 - "$tmp/victim" "$@" <<'PY' || fail "cannot plant"
import os, sys
nxt = os.getpid() + 1
for name in sys.argv[2:]:
    for p in range(nxt, nxt + 300):
        for t in ["%s.tmp-%d" % (name, p)] + ["%s.tmp.%d.%d" % (name, p, n) for n in range(3)]:
            os.symlink(sys.argv[1], t)
PY
}
intact() {
  [ "$(cat victim)" = precious ] || fail "the victim was overwritten through a symlink"
  for f in "$@"; do [ -f "$f" ] && [ ! -L "$f" ] || fail "$f is not a regular file"; done
  [ -z "$(find . -maxdepth 1 -name '*.tmp.*' -type f)" ] || fail "a temporary was left"
}
case "$case" in
optimize)
  plant best.yaml best.h5
  run "$bin" optimize "$scene" --vary winding.tension=50:500 --maximize winding.tension \
      --subject-to "core_pressure<=100000" -o best.yaml
  [ "$got" -eq 0 ] || fail "optimize failed"
  intact best.yaml best.h5
  "$bin" check best.yaml > /dev/null || fail "best.yaml does not load"
  ;;
run)
  mkdir csv
  plant out.h5 csv/small-profile.csv csv/small-wot.csv
  run "$bin" run "$scene" -o out.h5 --csv csv -q
  [ "$got" -eq 0 ] || fail "run failed"
  intact out.h5 csv/small-profile.csv csv/small-wot.csv
  ;;
sweep)
  plant sweep.h5 sweep.csv
  run "$bin" sweep "$scene" --vary winding.tension=100,200 -o sweep.h5 --csv sweep.csv -q
  [ "$got" -eq 0 ] || fail "sweep failed"
  intact sweep.h5 sweep.csv
  ;;
stale)
  dead=$(sh -c 'echo $$')  # a pid that has just ended
  kill -0 "$dead" 2>/dev/null && fail "pid $dead is alive"
  for f in "out.h5.tmp.$dead.0" "out.h5.tmp.$dead.7" "out.h5.tmp.$$.0" "other.h5.tmp.$dead.0"; do
    echo x > "$f"; touch -d '1 hour ago' "$f"
  done
  echo x > "out.h5.tmp.$dead.9"  # fresh: may be another machine's writer on a shared folder
  run "$bin" run "$scene" -o out.h5 -q
  [ "$got" -eq 0 ] || fail "run failed"
  for f in "out.h5.tmp.$dead.0" "out.h5.tmp.$dead.7"; do [ ! -e "$f" ] || fail "stale $f kept"; done
  for f in "out.h5.tmp.$$.0" "other.h5.tmp.$dead.0" "out.h5.tmp.$dead.9"; do
    [ -e "$f" ] || fail "$f removed"
  done
  ;;
*) fail "unknown case $case" ;;
esac
echo PASS

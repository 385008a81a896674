#!/usr/bin/env bash
# progress_tty.sh REELSIM SCENE: on a terminal (a pseudo-terminal from script(1)) a run
# longer than a second draws a progress bar on stderr; --quiet draws none.
set -u
bin="$1"; scene="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
command -v script >/dev/null || { echo "script(1) not available: skipped"; exit 0; }
# rtol 1e-11 and every increment from the core: 3.6 s on this machine, long enough for the
# bar however fast the engine gets (at rtol 1e-9 with the deep solution reused the run
# took 0.99 s, and no bar was due)
script -qec "'$bin' run '$scene' -o '$tmp/a.h5' --set numerics.rtol=1e-11 --set numerics.reuse=none" /dev/null > "$tmp/tty" 2>&1 || { cat "$tmp/tty"; fail "run on a pty failed"; }
grep -aEq 'reelsim: \[[#.]+\] +[0-9]+%  layer [0-9]+ of [0-9]+' "$tmp/tty" || { cat -A "$tmp/tty" | head -20; fail "no progress bar on a terminal"; }
grep -aq 'final radius' "$tmp/tty" || fail "no summary"
script -qec "'$bin' run '$scene' -o '$tmp/b.h5' --quiet" /dev/null > "$tmp/quiet" 2>&1 || fail "quiet run failed"
[ ! -s "$tmp/quiet" ] || { cat -A "$tmp/quiet" | head; fail "--quiet printed something on a terminal"; }
echo PASS

#!/usr/bin/env bash
# symbols_negative.sh CHECK-SYMBOLS CC
# scripts/check-symbols.sh refuses an object that defines a generic global (plot_x) and a
# shared library that exports an internal name (rsi_x) or a generic one, naming it; it
# passes the same files with the names fixed (static ones are not globals).
set -u
check=$1 cc=$2
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
printf 'int plot_x(void) { return 1; }\nint rs_y(void) { return 2; }\n' >"$t/bad.c"
printf 'static int plot_x(void) { return 1; }\nint rsi_plot_x(void) { return plot_x(); }\nint rs_y(void) { return 2; }\n' >"$t/good.c"
printf '__attribute__((visibility("default"))) int rsi_x(void) { return 1; }\n' >"$t/leak.c"
"$cc" -c -o "$t/bad.o" "$t/bad.c" && "$cc" -c -o "$t/good.o" "$t/good.c" || fail "cannot compile"
"$cc" -shared -fPIC -o "$t/leak.so" "$t/leak.c" || fail "cannot link a shared library"
"$cc" -shared -fPIC -fvisibility=hidden -o "$t/good.so" "$t/good.c" || fail "cannot link"
out=$(bash "$check" "$t/bad.o" 2>&1) && fail "plot_x passed: $out"
grep -q '^  plot_x$' <<<"$out" || fail "plot_x not named: $out"
out=$(bash "$check" "$t/leak.so" 2>&1) && fail "an exported rsi_x passed: $out"
grep -q 'rsi_x' <<<"$out" || fail "rsi_x not named: $out"
bash "$check" "$t/good.o" || fail "the fixed object was refused"
"$cc" -shared -fPIC -o "$t/open.so" "$t/good.c" || fail "cannot link"
bash "$check" "$t/open.so" >/dev/null 2>&1 && fail "a shared library exporting rsi_plot_x passed"
echo PASS

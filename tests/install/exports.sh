#!/usr/bin/env bash
# exports.sh LIBRARY
# The shared library exports the API and nothing else: every dynamic symbol it defines
# starts with rs_ (the library is compiled with hidden visibility; only what a public
# header declares between RS_BEGIN_DECLS and RS_END_DECLS is exported), and the names the
# API promises are there. A static library exports nothing: skipped (status 77).
set -u
. "$RS_SOURCE/tests/cli/lib.sh"
lib="$1"
case "$lib" in
  *.a) echo "SKIP: $lib is a static library (BUILD_SHARED_LIBS=OFF)"; exit 77 ;;
esac
syms="$(nm -D --defined-only "$lib" | awk 'NF == 3 { print $3 }' | sort)" || fail "nm -D $lib"
n="$(printf '%s\n' "$syms" | grep -c .)"
echo "$lib: $n exported symbols"
others="$(printf '%s\n' "$syms" | grep -v '^rs_')"
[ -z "$others" ] || { printf '%s\n' "$others"; fail "symbols without the rs_ prefix are exported"; }
for s in rs_scene_load rs_scene_load_text rs_scene_destroy rs_scene_problem rs_scene_wind rs_reel_wind rs_reel_result_destroy \
         rs_error_message rs_status_exit_code rs_version; do
  printf '%s\n' "$syms" | grep -qx "$s" || fail "$s is not exported"
done
echo "PASS"

#!/usr/bin/env bash
# The installed headers are an API a C or C++ program can use:
#   - every public header opens and closes its declarations with RS_BEGIN_DECLS /
#     RS_END_DECLS (what exports them from the shared library and gives them C linkage
#     in C++), none with a bare extern "C" (its functions would stay hidden);
#   - reelsim/reelsim.h includes every public header;
#   - each header compiles on its own (it includes what it uses), as C11, and the
#     umbrella header also as C++ when a C++ compiler is installed.
set -u
. "$RS_SOURCE/tests/install/lib.sh"
install_prefix
inc="$prefix/include"
cd "$inc/reelsim" || fail "no $inc/reelsim"
headers="$(ls -1 *.h)"
echo "installed headers:" $headers
for h in $headers; do
  case "$h" in export.h | reelsim.h) continue ;; esac
  grep -q '^RS_BEGIN_DECLS$' "$h" || fail "$h: no RS_BEGIN_DECLS line"
  grep -q '^RS_END_DECLS$' "$h" || fail "$h: no RS_END_DECLS line"
  ! grep -q 'extern "C"' "$h" || fail "$h: extern \"C\" (use RS_BEGIN_DECLS / RS_END_DECLS)"
  grep -q "^#include \"reelsim/$h\"" reelsim.h || fail "reelsim/reelsim.h does not include reelsim/$h"
done
for h in $headers; do
  printf '#include <reelsim/%s>\nint main(void) { return 0; }\n' "$h" > "$tmp/one.c"
  run "$RS_CC" -std=c11 -Wall -Wextra -Werror -fsyntax-only -I"$inc" "$tmp/one.c"
  [ "$got" -eq 0 ] || fail "reelsim/$h does not compile on its own as C11"
done
if command -v c++ >/dev/null; then
  printf '#include <reelsim/reelsim.h>\nint main() { return rs_version() ? 0 : 1; }\n' > "$tmp/api.cpp"
  run c++ -Wall -Wextra -Werror -fsyntax-only -I"$inc" "$tmp/api.cpp"
  [ "$got" -eq 0 ] || fail "reelsim/reelsim.h does not compile as C++"
else
  echo "(no c++: the C++ compile is not checked)"
fi
echo "PASS"

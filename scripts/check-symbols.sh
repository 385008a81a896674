#!/usr/bin/env bash
# The names the library leaves in a program (docs/architecture.md, "Names"):
#   - every global the library's objects define is either its API, rs_*, or internal with
#     the one reserved prefix rsi_* (no generic names such as plot_* to collide with a
#     program's own);
#   - a shared library exports its API, rs_*, and nothing else (not even rsi_*).
#
#   scripts/check-symbols.sh LIBRARY...     (.a or .o: the first rule; .so: both)
set -uo pipefail
[ $# -gt 0 ] || { echo "usage: check-symbols.sh LIBRARY..." >&2; exit 2; }
allow='^(rs_|rsi_)'
fail=0
for lib in "$@"; do
  case "$lib" in
    *.so | *.so.*)
      syms=$(nm -D --defined-only "$lib" | awk 'NF == 3 { print $3 }' | LC_ALL=C sort -u)
      bad=$(printf '%s\n' "$syms" | grep -Ev '^rs_' | grep -v '^$'; printf '%s\n' "$syms" | grep -E '^rsi_'; true)
      what="exports symbols other than rs_*"
      n=$(printf '%s\n' "$syms" | grep -c .); ok="$n exported symbols, all rs_*" ;;
    *)
      syms=$(nm --defined-only "$lib" 2>/dev/null | awk 'NF == 3 && $2 ~ /^[TDBRCGSV]$/ { print $3 }' |
             LC_ALL=C sort -u)
      # AddressSanitizer marks each global variable with its own __odr_asan.<name>
      bad=$(printf '%s\n' "$syms" | grep -v '^__odr_asan\.' | grep -Ev "$allow" | grep -v '^$'; true)
      what="defines globals without the rs_ or rsi_ prefix"
      n=$(printf '%s\n' "$syms" | grep -c .); ok="$n globals, all rs_* or rsi_*" ;;
  esac
  if [ -n "$bad" ]; then
    printf '%s\n' "$bad" | sed 's/^/  /' >&2
    echo "check-symbols: $lib $what (above)" >&2
    fail=1
  else
    echo "check-symbols: $lib: $ok"
  fi
done
exit "$fail"

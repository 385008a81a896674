#!/usr/bin/env bash
# The layer check (docs/architecture.md): fails when a file includes a header of a higher
# layer, when the CLI includes anything but the public headers and its own, when files
# include each other in a cycle, or (given the library's object files) when an object file
# calls a higher layer or object files call each other in a cycle.
#
#   scripts/check-layers.sh ROOT [OBJECT.o ...]
#
# ROOT is the source tree (its src/ and include/ are read). Every #include "..." of
# src/**/*.[ch] and include/reelsim/*.h is checked; system headers (<...>) are not.
# A file or header the map below does not place is an error: a new directory or public
# header must be given its layer here (and in docs/architecture.md).
set -uo pipefail

root=${1:?usage: check-layers.sh ROOT [OBJECT.o ...]}
shift
cd "$root" || exit 2

names=(base laws roll-nip reel scene io plot study sweep cli)

# layer_of PATH -> the layer number of a file (relative to ROOT), or nothing.
layer_of() {
  case "$1" in
    include/reelsim/status.h | include/reelsim/version.h | include/reelsim/export.h | \
      include/reelsim/clock.h | src/error.c | src/clock.c | src/version.c | \
      src/util/*) echo 0 ;;
    include/reelsim/material.h | include/reelsim/core.h | include/reelsim/recipe.h | \
      include/reelsim/numerics.h | src/material/* | src/recipe/* | src/sheet/* | src/cylinder/*) echo 1 ;;
    include/reelsim/nip.h | src/roll/* | src/nip/*) echo 2 ;;
    include/reelsim/problem.h | include/reelsim/reel.h | include/reelsim/defects.h | \
      include/reelsim/storage.h | src/storage/* | \
      src/reel/*) echo 3 ;;
    include/reelsim/scene.h | src/scene/*) echo 4 ;;
    include/reelsim/output.h | include/reelsim/reader.h | src/output/*) echo 5 ;;
    include/reelsim/plot.h | src/plot/*) echo 6 ;;
    include/reelsim/study.h | src/study/* | include/reelsim/fit.h | src/fit/*) echo 7 ;; # study, fit
    src/sweep/*) echo 8 ;;                          # recipe search: an application
    include/reelsim/reelsim.h | src/cli/*) echo 9 ;; # the umbrella header: applications only
  esac
}

# resolve INCLUDER NAME -> the included file relative to ROOT; "generated" for a header
# made by the build (reelsim/version.h); nothing if unknown.
resolve() {
  local from=$1 name=$2
  if [ -f "include/$name" ]; then echo "include/$name"
  elif [ -f "src/$name" ]; then echo "src/$name"
  elif [ -f "$(dirname "$from")/$name" ]; then echo "$(dirname "$from")/$name"
  else
    case "$name" in reelsim_*.h | reelsim/*.h) echo generated ;; esac
  fi
}

fail=0
err() { echo "check-layers: $*" >&2; fail=1; }
edges=$(mktemp)
trap 'rm -f "$edges"' EXIT

files=$( { find src -type f \( -name '*.c' -o -name '*.h' \) 2>/dev/null;
           find include/reelsim -type f -name '*.h' 2>/dev/null; } | LC_ALL=C sort)
for f in $files; do
  lf=$(layer_of "$f")
  if [ -z "$lf" ]; then
    err "$f: not placed in a layer (add it to scripts/check-layers.sh and docs/architecture.md)"
    continue
  fi
  while IFS=: read -r line name; do
    [ -n "$name" ] || continue
    to=$(resolve "$f" "$name")
    if [ -z "$to" ]; then
      err "$f:$line: #include \"$name\": no such header in src/ or include/"
      continue
    fi
    if [ "$to" = generated ]; then lt=0; else
      lt=$(layer_of "$to")
      [ -n "$lt" ] || { err "$f:$line: #include \"$name\": $to is not placed in a layer"; continue; }
      echo "$f $to" >>"$edges"
    fi
    if [ "$lt" -gt "$lf" ]; then
      err "$f:$line: the ${names[$lf]} layer includes \"$name\" of the higher ${names[$lt]} layer"
    fi
    # The applications stand on the public API: reelsim/*.h (and the generated version
    # header); the CLI also on its own cli/*.h and the recipe search's sweep/*.h, the
    # recipe search on its own sweep/*.h.
    case "$f" in
      src/cli/*)
        case "$name" in
          reelsim/*.h | cli/*.h | sweep/*.h) ;;
          *) err "$f:$line: the CLI includes \"$name\", not a public header (reelsim/*.h)" ;;
        esac ;;
      src/sweep/*)
        case "$name" in
          reelsim/*.h | sweep/*.h) ;;
          *) err "$f:$line: the recipe search includes \"$name\", not a public header (reelsim/*.h)" ;;
        esac ;;
    esac
  done < <(sed -n -E 's/^[[:space:]]*#[[:space:]]*include[[:space:]]+"([^"]+)".*/\1/p;t;s/.*//p' "$f" |
             awk '{ if ($0 != "") print NR ":" $0 }')
done

# Include cycles: two files including each other, directly or through others.
if ! out=$(tsort <"$edges" 2>&1 >/dev/null); then
  err "include cycle:"$'\n'"$out"
fi

# The object files given: who calls whom, from their defined and undefined symbols (nm).
# A call into a higher layer fails (a local prototype gets past the include check, not
# past this), and so does a call cycle (a calls b and b calls a, directly or through
# others), which no #include line shows when one header declares both.
if [ $# -gt 0 ]; then
  if ! command -v nm >/dev/null; then
    err "nm not found: cannot check the object files"
  else
    syms=$(mktemp)
    trap 'rm -f "$edges" "$syms"' EXIT
    for o in "$@"; do
      n=${o##*/src/}; n=${n%.o}; n=${n%.c}
      nm "$o" | awk -v n="$n" 'NF == 3 && $2 ~ /^[TDBRC]$/ { print "D", $3, n }
                                NF == 2 && $1 == "U" { print "U", $2, n }'
    done >"$syms"
    # "caller callee symbol", one line per symbol
    calls=$(awk '$1 == "D" { def[$2] = $3; next } { use[NR] = $3 " " $2 }
                 END { for (k in use) { split(use[k], u, " ");
                         if ((u[2] in def) && def[u[2]] != u[1]) print u[1], def[u[2]], u[2] } }' \
              "$syms" | LC_ALL=C sort -u)
    while read -r from to sym; do
      [ -n "$from" ] || continue
      lf=$(layer_of "src/$from.c") lt=$(layer_of "src/$to.c")
      if [ -n "$lf" ] && [ -n "$lt" ] && [ "$lt" -gt "$lf" ]; then
        err "src/$from.c calls $sym of src/$to.c: the ${names[$lf]} layer calls the higher ${names[$lt]} layer"
      fi
    done <<<"$calls"
    if ! out=$(printf '%s\n' "$calls" | cut -d' ' -f1,2 | tsort 2>&1 >/dev/null); then
      err "call cycle between object files:"$'\n'"$out"
    fi
  fi
fi

[ "$fail" -eq 0 ] && echo "check-layers: $(echo "$files" | wc -l) files, every include within its" \
  "layer or below, no cycles${1:+; $# object files: no call upwards, no call cycle}"
exit "$fail"

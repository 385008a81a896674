#!/usr/bin/env bash
# Builds reelsim against a SUNDIALS 7.x built from its source, and runs the unit and
# validation tests on it (docs/development.md, "SUNDIALS 6.4 and 7.x").
#
#   bash scripts/check-sundials7.sh SUNDIALS_SOURCE [WORK_DIR]
#
# SUNDIALS_SOURCE: a SUNDIALS source tree (a release tarball unpacked, or
# `git clone --branch v7.5.0 https://github.com/LLNL/sundials`); its sundials_config.h
# must say 7.x. WORK_DIR (default /tmp/reelsim-sundials7): SUNDIALS' build in build-sundials/,
# its install in sundials/, reelsim's build in build-reelsim/; nothing is written into the
# source trees. SUNDIALS is built as scripts/build-sundials.sh builds Debian's 6.4 (CVODE,
# serial N_Vector, dense matrix and linear solver, Newton, static -fPIC -O2, no MPI,
# examples or Fortran), reelsim as a developer build (warnings are errors).
# Not run in CI: CI has no network to fetch SUNDIALS 7, and bookworm ships 6.4.
# Environment: RS_JOBS (default 1: the build is niced and single-threaded),
# RS_CTEST_ARGS (default: -L 'unit|validation' -E '^valgrind\.').
set -euo pipefail
src="${1:?usage: check-sundials7.sh SUNDIALS_SOURCE [WORK_DIR]}"
work="${2:-/tmp/reelsim-sundials7}"
jobs="${RS_JOBS:-1}"
root="$(cd "$(dirname "$0")/.." && pwd)"
[ -f "$src/CMakeLists.txt" ] && [ -d "$src/src/cvode" ] ||
  { echo "check-sundials7: $src is not a SUNDIALS source tree (no CMakeLists.txt, src/cvode)" >&2; exit 2; }
src="$(cd "$src" && pwd)"
mkdir -p "$work"
work="$(cd "$work" && pwd)"
prefix="$work/sundials"

echo "== SUNDIALS from $src into $prefix =="
. "$root/scripts/sundials-options.sh"
nice -n 19 cmake -S "$src" -B "$work/build-sundials" "${SUNDIALS_CMAKE_OPTIONS[@]}" \
  -DCMAKE_INSTALL_PREFIX="$prefix" > "$work/sundials-configure.log"
nice -n 19 cmake --build "$work/build-sundials" -j "$jobs" > "$work/sundials-build.log"
cmake --install "$work/build-sundials" > "$work/sundials-install.log"
version="$(sed -n 's/^#define SUNDIALS_VERSION "\(.*\)"$/\1/p' "$prefix/include/sundials/sundials_config.h")"
case "$version" in
  7.*) echo "SUNDIALS $version installed" ;;
  *) echo "check-sundials7: the source built SUNDIALS '$version', not 7.x" >&2; exit 2 ;;
esac

echo "== reelsim against SUNDIALS $version (developer build: warnings are errors) =="
nice -n 19 cmake -S "$root" -B "$work/build-reelsim" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DREELSIM_DEVELOPER=ON -DREELSIM_SIMD=ON -DREELSIM_SUNDIALS_ROOT="$prefix" \
  ${RS_CMAKE_ARGS:-} > "$work/reelsim-configure.log"
grep -q "SUNDIALS $version" "$work/reelsim-configure.log" ||
  { echo "check-sundials7: reelsim did not configure against SUNDIALS $version" >&2; exit 1; }
nice -n 19 cmake --build "$work/build-reelsim" -j "$jobs" > "$work/reelsim-build.log"

echo "== tests =="
# shellcheck disable=SC2086
(cd "$work/build-reelsim" && nice -n 19 ctest -j "$jobs" --output-on-failure \
  ${RS_CTEST_ARGS:--L 'unit|validation' -E '^valgrind\.'})

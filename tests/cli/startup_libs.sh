#!/usr/bin/env bash
# startup_libs.sh REELSIM REGEX: the shared libraries the program loads at start (ldd) include
# none whose name matches REGEX (grep -E): those it links statically (HDF5, LAPACKE/OpenBLAS,
# its own library: CMake REELSIM_STATIC_DEPS) or opens only under mpirun (Open MPI, through
# its module reelsim-mpi.so). docs/performance.md, "What remains outside the engine".
set -u
. "$(dirname "$0")/lib.sh" # fail, run, has
bin=$1 regex=$2
run ldd "$bin"
[ "$got" -eq 0 ] || fail "ldd failed"
echo "$(printf '%s\n' "$out" | grep -c '=>') shared libraries"
bad=$(printf '%s\n' "$out" | grep -E -- "$regex")
[ -z "$bad" ] || fail "loaded at start: $bad"
echo "PASS: none matches /$regex/"

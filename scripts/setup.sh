#!/usr/bin/env bash
# Installs the Debian packages reelsim needs (only those missing), then configures
# and builds into build/ (or $RS_BUILD_DIR). Safe to run again: a no-op when all is there.
set -euo pipefail
cd "$(dirname "$0")/.."

PKGS="build-essential cmake pkg-config libsundials-dev libhdf5-dev liblapacke-dev libyaml-dev hdf5-tools gnuplot-nox valgrind libopenblas0-serial libopenblas-serial-dev clang libclang-rt-14-dev python3-numpy python3-h5py python3-pytest python3-matplotlib libopenmpi-dev openmpi-bin libnlopt-dev libudunits2-dev"
missing=""
for p in $PKGS; do
  dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "setup: installing missing Debian packages:$missing" >&2
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  # shellcheck disable=SC2086
  $SUDO apt-get install -y -q --no-install-recommends $missing
fi

# An optimised CVODE built from Debian's own source of the installed libsundials-dev
# (scripts/build-sundials.sh; bookworm's is compiled without optimisation), cached under
# ~/.cache/reelsim and linked statically into libreelsim. RS_SYSTEM_SUNDIALS=1, or any
# failure (offline, no deb-src), builds against the system's libsundials instead.
SUNDIALS_ROOT=""
if [ "${RS_SYSTEM_SUNDIALS:-0}" != 1 ]; then
  SUNDIALS_ROOT="$(bash scripts/build-sundials.sh)" || SUNDIALS_ROOT=""
fi

BUILD_DIR="${RS_BUILD_DIR:-build}"
# A developer/CI build: warnings are errors, and AVX2 where this machine has it (a plain
# `cmake -S . -B b` is the portable build a user of the library gets).
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE="${RS_BUILD_TYPE:-RelWithDebInfo}" \
  -DREELSIM_DEVELOPER=ON -DREELSIM_SIMD=ON -DREELSIM_SUNDIALS_ROOT="$SUNDIALS_ROOT" \
  ${RS_CMAKE_ARGS:-} >/dev/null
cmake --build "$BUILD_DIR" -j "$(nproc)"

#!/usr/bin/env bash
# Builds the CVODE reelsim links from Debian's own source of the installed libsundials-dev,
# with optimisation, and prints the install prefix (for -DREELSIM_SUNDIALS_ROOT=...).
# Run by scripts/setup.sh; exits 1 with a one-line note on stderr when it cannot (offline,
# no deb-src, a version mismatch, a failed build): the build then uses the system library.
#
# Why: bookworm's libsundials is compiled without optimisation (debian/rules sets
# CMAKE_C_FLAGS=-fcommon, which replaces dpkg's -O2): CVODE's step-size selection and
# linear-algebra helpers run at -O0 (docs/performance.md, issue 17).
#
# What: `apt-get source sundials=<installed version>` (Debian's patches applied), through a
# private apt state (its own deb-src list and package lists; the system's apt
# configuration is not touched), SUNDIALS' own CMake building CVODE and the modules it uses
# (serial N_Vector, dense matrix and linear solver, Newton solver) as static -fPIC -O2
# libraries, no MPI/OpenMP/Fortran/examples, installed into
#   ${XDG_CACHE_HOME:-$HOME/.cache}/reelsim/sundials-<version>-O2
# and reused while its stamp matches this recipe. Only reelsim's build reads it: the static
# libraries are linked into libreelsim, which does not need the cache at run time.
set -euo pipefail

note() { echo "setup: $* (using the system's libsundials)" >&2; exit 1; }

command -v dpkg-query >/dev/null 2>&1 || note "no dpkg-query: not a Debian system"
version="$(dpkg-query -W -f='${Version}' libsundials-dev 2>/dev/null)" ||
  note "libsundials-dev is not installed"
[ -n "${XDG_CACHE_HOME:-}${HOME:-}" ] || note "neither XDG_CACHE_HOME nor HOME is set (no cache folder)"
cache="${XDG_CACHE_HOME:-$HOME/.cache}/reelsim"
prefix="$cache/sundials-$version-O2"
# Everything that makes the build (the cmake line below): a different recipe is rebuilt.
recipe="reelsim sundials $version; cflags -O2 -fcommon -fPIC; static; cvode nvecserial sunmatrixdense sunlinsoldense; $(cc --version 2>/dev/null | head -n 1 || true)"
stamp="$prefix/reelsim-stamp"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$recipe" ]; then
  echo "$prefix"
  exit 0
fi

for t in apt-get dpkg-source dpkg-parsechangelog cmake cc flock; do
  command -v "$t" >/dev/null 2>&1 || note "no $t to build an optimised CVODE"
done
mkdir -p "$cache" || note "cannot create $cache"
# One build at a time (two setup.sh runs share the cache).
exec 9> "$cache/.sundials.lock"
flock 9
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$recipe" ]; then
  echo "$prefix"
  exit 0
fi

work="$(mktemp -d "${TMPDIR:-/tmp}/reelsim-sundials.XXXXXX")" || note "mktemp failed"
trap 'rm -rf "$work"' EXIT
log="$work/log"
fail() {
  cp "$log" "$cache/sundials-build.log" 2>/dev/null || true
  note "$1; see $cache/sundials-build.log"
}

# A private apt state: a deb-src list of its own, package lists and cache under $work.
apt="$work/apt"
mkdir -p "$apt/lists/partial" "$apt/cache/archives/partial" "$work/src"
codename="$(. /etc/os-release 2>/dev/null && echo "${VERSION_CODENAME:-}")"
[ -n "$codename" ] || fail "no VERSION_CODENAME in /etc/os-release"
cat > "$apt/deb-src.sources" <<EOF
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: $codename
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
APT_OPTS=(-q -o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$apt"
          -o "Dir::State::Lists=$apt/lists" -o "Dir::Cache=$apt/cache"
          -o "APT::Sandbox::User=$(id -un)" -o "Acquire::http::Timeout=15" -o "Acquire::Retries=1")
# apt-get update reports an unreachable archive as a warning: look for the Sources index.
apt-get "${APT_OPTS[@]}" update >> "$log" 2>&1 &&
  compgen -G "$apt/lists/*Sources*" > /dev/null ||
  fail "no deb-src index from deb.debian.org (offline?)"
(cd "$work/src" && apt-get "${APT_OPTS[@]}" source "sundials=$version") >> "$log" 2>&1 ||
  fail "apt-get source sundials=$version failed (no such source version?)"
srcdir="$(find "$work/src" -mindepth 1 -maxdepth 1 -type d -name 'sundials-*' | head -n 1)"
[ -n "$srcdir" ] || fail "apt-get source left no sundials-* directory"
# Headers and library must be the same release as the installed package's.
got="$(dpkg-parsechangelog -l "$srcdir/debian/changelog" -S Version 2>> "$log")" ||
  fail "cannot read the source's debian/changelog"
[ "$got" = "$version" ] || fail "the source is sundials $got, the installed libsundials-dev is $version"

echo "setup: building an optimised CVODE from Debian's source of sundials $version (once; log in $cache/sundials-build.log)" >&2
build="$work/build"
. "$(dirname "$0")/sundials-options.sh"
cmake -S "$srcdir" -B "$build" "${SUNDIALS_CMAKE_OPTIONS[@]}" -DCMAKE_C_FLAGS="-fcommon" \
  -DCMAKE_INSTALL_PREFIX="$prefix" >> "$log" 2>&1 ||
  fail "configuring SUNDIALS failed"
cmake --build "$build" -j "$(nproc)" >> "$log" 2>&1 || fail "building SUNDIALS failed"
rm -rf "$prefix"
cmake --install "$build" >> "$log" 2>&1 || { rm -rf "$prefix"; fail "installing SUNDIALS failed"; }
# the same release as the system headers say (SUNDIALS_VERSION in sundials_config.h)
v_sys="$(sed -n 's/^#define SUNDIALS_VERSION "\(.*\)"$/\1/p' /usr/include/sundials/sundials_config.h 2>/dev/null)"
v_opt="$(sed -n 's/^#define SUNDIALS_VERSION "\(.*\)"$/\1/p' "$prefix/include/sundials/sundials_config.h")"
[ -n "$v_opt" ] && [ "$v_opt" = "$v_sys" ] ||
  { rm -rf "$prefix"; fail "built SUNDIALS $v_opt, the system headers are $v_sys"; }
cp "$log" "$cache/sundials-build.log" 2>/dev/null || true
printf '%s\n' "$recipe" > "$stamp"
echo "$prefix"

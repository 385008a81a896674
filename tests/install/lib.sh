# Shared by the install tests (source it). From the environment (tests/install/install.cmake):
#   RS_BUILD, RS_SOURCE   the build and source trees;  RS_CMAKE, RS_CC  cmake, the C compiler
#   RS_LIBDIR, RS_BINDIR, RS_DATADIR   the install layout (relative to the prefix)
#   RS_STATIC             1 when libreelsim is a static library
#   RS_CONSUMER_CFLAGS    what a program linking this build's library must be compiled with
#                         (the sanitizers in an ASan build)
# install_prefix: `cmake --install` of the build into a fresh prefix outside the source and
# build trees ($prefix, resolved; all under $tmp, removed on exit).
. "$RS_SOURCE/tests/cli/lib.sh"
unset REELSIM_MODELS

install_prefix() {
  tmp="$(mktemp -d "${TMPDIR:-/tmp}/reelsim-install.XXXXXX")" || fail "mktemp"
  trap 'rm -rf "$tmp"' EXIT
  tmp="$(cd "$tmp" && pwd -P)"
  prefix="$tmp/prefix"
  "$RS_CMAKE" --install "$RS_BUILD" --prefix "$prefix" > "$tmp/install.log" 2>&1 ||
    { cat "$tmp/install.log"; fail "cmake --install failed"; }
  echo "installed into $prefix:"
  (cd "$prefix" && find . -type f | sort | sed 's/^/  /')
}

# core_pressure: the "NNN.N Pa" of wind_scene's output ($out)
core_pressure() {
  printf '%s\n' "$out" | sed -n 's/.*core pressure \([0-9.eE+-]*\) Pa$/\1/p' | head -n 1
}

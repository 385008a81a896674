#!/usr/bin/env bash
# consumer.sh find_package|pkg_config
# A program outside the tree (examples/wind_scene.c) built against an installed reelsim,
# with CMake's find_package(reelsim CONFIG) or with pkg-config, and run on a shipped case
# cut short: its core pressure must be a positive number, the installed program's figure.
set -u
. "$RS_SOURCE/tests/install/lib.sh"
mode="$1"
install_prefix
scene="$RS_SOURCE/cases/newsprint-rider.yaml"
set="winding.final_radius=0.1"

run "$prefix/$RS_BINDIR/reelsim" run "$scene" --set "$set" -o "$tmp/cli.h5"
[ "$got" -eq 0 ] || fail "the installed reelsim failed"
run h5dump -m '%.1f' -d /final/core_pressure "$tmp/cli.h5"
want="$(printf '%s\n' "$out" | sed -n 's/^ *(0): \([0-9.eE+-]*\)$/\1/p' | head -n 1)"
[ -n "$want" ] || fail "no /final/core_pressure in the installed reelsim's output"

exe="$tmp/wind_scene"
case "$mode" in
  find_package)
    run "$RS_CMAKE" -S "$RS_SOURCE/examples" -B "$tmp/build" -DCMAKE_PREFIX_PATH="$prefix" \
        -DCMAKE_C_COMPILER="$RS_CC" -DCMAKE_C_FLAGS="$RS_CONSUMER_CFLAGS"
    [ "$got" -eq 0 ] || fail "configuring examples/ against $prefix failed"
    grep -qx "reelsim_DIR:PATH=$prefix/$RS_LIBDIR/cmake/reelsim" "$tmp/build/CMakeCache.txt" ||
      fail "find_package did not take the package installed in $prefix"
    run "$RS_CMAKE" --build "$tmp/build"
    [ "$got" -eq 0 ] || fail "building examples/ failed"
    exe="$tmp/build/wind_scene"
    ;;
  pkg_config)
    export PKG_CONFIG_PATH="$prefix/$RS_LIBDIR/pkgconfig"
    static=""
    [ "$RS_STATIC" = 1 ] && static="--static"
    run pkg-config --modversion reelsim
    has "^$(sed -n 's/^project(reelsim VERSION \([0-9.]*\).*/\1/p' "$RS_SOURCE/CMakeLists.txt")\$"
    flags="$(pkg-config $static --cflags --libs reelsim)" || fail "pkg-config --cflags --libs reelsim failed"
    echo "pkg-config: $flags"
    # shellcheck disable=SC2086
    run "$RS_CC" $RS_CONSUMER_CFLAGS -o "$exe" "$RS_SOURCE/examples/wind_scene.c" $flags
    [ "$got" -eq 0 ] || fail "compiling examples/wind_scene.c with pkg-config's flags failed"
    export LD_LIBRARY_PATH="$prefix/$RS_LIBDIR"
    ;;
  *) fail "unknown mode $mode" ;;
esac

if [ "$RS_STATIC" != 1 ]; then
  # the installed shared library, not the build tree's
  run ldd "$exe"
  has "libreelsim\.so.* => $prefix/$RS_LIBDIR/libreelsim\.so"
fi
run "$exe" "$scene" "$set"
[ "$got" -eq 0 ] || fail "wind_scene failed"
has "^reelsim ([0-9.]+) \(headers \1\)$"
has "core pressure [0-9.]+ Pa$"
p="$(core_pressure)"
awk -v p="$p" 'BEGIN { exit !(p > 0) }' || fail "core pressure '$p' is not a positive number"
[ "$p" = "$want" ] || fail "core pressure $p Pa, the installed reelsim wrote $want Pa"
echo "PASS: core pressure $p Pa, as the installed reelsim wrote"

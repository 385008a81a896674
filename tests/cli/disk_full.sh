#!/usr/bin/env bash
# disk_full.sh REELSIM SCENE MODE: the output cannot be written; `run` exits 1 saying why,
# and leaves no file under the output name and no temporary.
#   fsize     a file-size limit (ulimit -f 4: 4 KiB) below the file's size, as a full disk
#             does: write() fails (EFBIG; without SIGXFSZ ignored the signal would kill
#             reelsim mid-write and leave its temporary behind)
#   readonly  the output directory is read-only (as root: run as nobody via setpriv,
#             since root writes anyway; skipped, status 77, if that is not possible)
set -u
bin="$1"; scene="$2"; mode="$3"
tmp="$(mktemp -d)"; trap 'chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
mkdir "$tmp/out"
case "$mode" in
  fsize)
    out="$( (ulimit -f 4; exec "$bin" run "$scene" -o "$tmp/out/r.h5") 2>&1)"; got=$?
    regex="cannot write output file '.*/out/r\.h5' \(temporary '.*'\): File too large" ;;
  readonly)
    chmod 555 "$tmp/out"; chmod 755 "$tmp"
    if [ "$(id -u)" -eq 0 ]; then
      command -v setpriv >/dev/null || { echo "SKIP: root without setpriv"; exit 77; }
      setpriv --reuid=65534 --regid=65534 --clear-groups true 2>/dev/null ||
        { echo "SKIP: cannot drop to nobody"; exit 77; }
      setpriv --reuid=65534 --regid=65534 --clear-groups test -x "$bin" -a -r "$scene" ||
        { echo "SKIP: nobody cannot run $bin on $scene"; exit 77; }
      out="$(setpriv --reuid=65534 --regid=65534 --clear-groups "$bin" run "$scene" -o "$tmp/out/r.h5" 2>&1)"; got=$?
    else
      out="$("$bin" run "$scene" -o "$tmp/out/r.h5" 2>&1)"; got=$?
    fi
    regex="cannot create output file '.*/out/r\.h5' \(directory '.*/out' is not writable" ;;
  *) fail "unknown mode $mode" ;;
esac
printf '%s\n' "$out"
echo "exit status: $got (expected 1)"
[ "$got" -eq 1 ] || fail "wrong exit status"
printf '%s\n' "$out" | grep -Eq -- "$regex" || fail "output does not match /$regex/"
[ -z "$(ls -A "$tmp/out")" ] || { ls -la "$tmp/out"; fail "files were left in the output directory"; }
echo PASS

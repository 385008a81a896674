# Shared by the CLI test scripts (source it): fail, run (output in $out, status in $got,
# both printed for the log), has (the last output matches a regex), is_png (a real,
# non-trivial PNG file).
fail() { echo "FAIL: $*"; exit 1; }
run() { out="$("$@" 2>&1)"; got=$?; printf '%s\n' "$out"; echo "exit status: $got"; }
has() { printf '%s\n' "$out" | grep -Eq -- "$1" || fail "output lacks /$1/"; }
is_png() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] ||
             fail "$1 is not a PNG"; [ "$(stat -c %s "$1")" -gt 10000 ] || fail "$1 is tiny"; }

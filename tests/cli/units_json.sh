#!/usr/bin/env bash
# units_json.sh REELSIM SMALL_SCENE: a slip warning reaches stderr and `run --json`'s
# `warnings` array (docs/cli.md); a scene without slips has an empty array.
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; small="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
"$bin" run "$small" --json -o "$tmp/s.h5" --set winding.speed=600 >"$tmp/run.json" 2>"$tmp/run.err" \
  || { cat "$tmp/run.err"; fail "run --json: exit $?"; }
cat "$tmp/run.json" "$tmp/run.err"
grep -q 'warning: --set winding.speed=600: winding.speed 600 m/s: did you mean 600 m/min?' "$tmp/run.err" \
  || fail "no warning on stderr"
python3 - "$tmp/run.json" <<'PY' || fail "warnings in --json"
import json, sys
j = json.load(open(sys.argv[1]))
w = j["warnings"]
assert isinstance(w, list) and len(w) == 1, w
assert "winding.speed 600 m/s: did you mean 600 m/min?" in w[0], w
PY
"$bin" run "$small" --json -o "$tmp/t.h5" >"$tmp/ok.json" 2>"$tmp/ok.err" || fail "run --json without a slip"
[ -s "$tmp/ok.err" ] && { cat "$tmp/ok.err"; fail "stderr without a slip"; }
python3 -c 'import json,sys; assert json.load(open(sys.argv[1]))["warnings"] == []' "$tmp/ok.json" \
  || fail "warnings not empty"
echo PASS

#!/usr/bin/env bash
# tutorial.sh REELSIM TUTORIAL_MD: follows docs/tutorial.md word for word in a scratch
# folder: saves its YAML block as my-film.yaml, runs every `./build/reelsim` command of its
# sh blocks (exit 0, or 2 where the line says "# exit 2"), and checks that every output
# line the page shows (its plain ``` blocks, "..." lines aside) is printed by one of them.
set -u
. "$(dirname "$0")/lib.sh"
bin="$1"; md="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
python3 - "$bin" "$md" "$tmp" <<'PY' || fail "the tutorial does not run as written"
import re, shlex, subprocess, sys
binary, md, tmp = sys.argv[1:4]
blocks = re.findall(r"^```(\w*)\n(.*?)^```", open(md, encoding="utf-8").read(), re.S | re.M)
yaml = [b for lang, b in blocks if lang == "yaml"]
assert len(yaml) == 1, "one yaml block"
open(tmp + "/my-film.yaml", "w").write(yaml[0])
out = ""
cmds = [l for lang, b in blocks if lang == "sh" for l in b.splitlines() if l.startswith("./build/reelsim")]
assert len(cmds) >= 5, cmds
for line in cmds:
    want = 2 if "# exit 2" in line else 0
    args = shlex.split(line.split("#")[0])
    args[0] = binary
    p = subprocess.run(args, cwd=tmp, capture_output=True, text=True)
    print("$", line, "->", p.returncode)
    print(p.stdout + p.stderr)
    assert p.returncode == want, "%s: exit %d, expected %d" % (line, p.returncode, want)
    out += p.stdout + p.stderr
lines = set(out.splitlines())
shown = [l for lang, b in blocks if lang == "" for l in b.splitlines() if l.strip() != "..."]
missing = [l for l in shown if l not in lines]
assert not missing, "shown but not printed: %r" % missing
print("%d commands, %d output lines as shown" % (len(cmds), len(shown)))
PY
echo PASS

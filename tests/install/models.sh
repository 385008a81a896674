#!/usr/bin/env bash
# An installed reelsim, run on a scene outside the source tree that names a shipped
# material model, finds it under <prefix>/<datadir>/reelsim/models (the prefix is not the
# one the build was configured for: the lookup follows the installed files); without the
# installed models it is a clear input error naming where it looked; $REELSIM_MODELS
# comes before the installed models. The same when the program is found through PATH.
set -u
. "$RS_SOURCE/tests/install/lib.sh"
install_prefix
bin="$prefix/$RS_BINDIR/reelsim"
models="$prefix/$RS_DATADIR/reelsim/models"
mkdir "$tmp/work"
cp "$RS_SOURCE/tests/install/newsprint-small.yaml" "$tmp/work/scene.yaml"
cd "$tmp/work" || fail "cd"

run "$bin" check scene.yaml
[ "$got" -eq 0 ] || fail "check failed"
has "^  source: $models/newsprint\.yaml$"
# found through PATH (its argv[0] is then the bare name), from a folder named like it
mkdir reelsim
run env PATH="$prefix/$RS_BINDIR:$PATH" reelsim check scene.yaml
[ "$got" -eq 0 ] || fail "check through PATH failed"
has "^  source: $models/newsprint\.yaml$"
rmdir reelsim
run "$bin" run scene.yaml -o out.h5
[ "$got" -eq 0 ] || fail "run failed"
has "core pressure +[0-9.]+ [kM]?Pa"
[ -s out.h5 ] || fail "no out.h5"

mkdir "$tmp/mine"
sed 's/^caliper:.*/caliper: 80.0e-6/' "$models/newsprint.yaml" > "$tmp/mine/newsprint.yaml"
run env REELSIM_MODELS="$tmp/mine" "$bin" check scene.yaml
[ "$got" -eq 0 ] || fail "check with REELSIM_MODELS failed"
has "^  source: $tmp/mine/newsprint\.yaml$"

mv "$models" "$models.gone"
run "$bin" check scene.yaml
[ "$got" -eq 2 ] || fail "a missing model must be exit status 2"
has "no material model 'newsprint'"
has "$models/newsprint\.yaml"
echo "PASS"

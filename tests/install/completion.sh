#!/usr/bin/env bash
# `cmake --install` puts the bash completion at <prefix>/share/bash-completion/completions/
# reelsim (where bash-completion looks for it), and it completes the installed program.
set -u
. "$RS_SOURCE/tests/install/lib.sh"
install_prefix
f="$prefix/$RS_DATADIR/bash-completion/completions/reelsim"
[ -f "$f" ] || fail "no $f"
bash -c '. "$1"; COMP_WORDS=(reelsim ru); COMP_CWORD=1; _reelsim; [ "${COMPREPLY[*]}" = run ]' _ "$f" ||
  fail "the installed completion does not complete 'ru' to 'run'"
echo PASS

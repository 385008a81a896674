#!/usr/bin/env bash
# help.sh REELSIM SCENES CMD: the command line of one command, as docs/cli.md gives it.
#   CMD (run, check, compare, plot, study, nip, sweep): `reelsim help CMD` and `reelsim CMD --help`
#     (and -h) exit 0 with the same text, which lists every flag of the command; an
#     unknown flag exits 2 naming it; where the command takes --set, both --set KEY=VALUE
#     and --set=KEY=VALUE reach the scene (a bad value is refused the same way, exit 2).
#   general: `reelsim --help` and `reelsim help` list every command; `reelsim help bogus`
#     exits 2.
set -u
bin="$1"; sc="$2"; cmd="$3"
. "$(dirname "$0")/lib.sh" # fail, run, has
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1

commands="run check compare plot study nip sweep optimize"
if [ "$cmd" = general ]; then
  for how in --help -h help "help help" "help --help" "help -h"; do
    run "$bin" $how
    [ "$got" -eq 0 ] || fail "reelsim $how: exit $got"
    for c in $commands help; do has "^  $c( |$)"; done
  done
  run "$bin" help bogus
  [ "$got" -eq 2 ] || fail "help bogus: exit $got, expected 2"
  has "help: unknown command 'bogus' \(commands: run, check, compare, plot, study, nip, sweep, optimize, help\)"
  echo PASS; exit 0
fi

# the flags docs/cli.md gives each command
case "$cmd" in
run)     flags="-o --output --csv -s --set -q --quiet --keep-partial -v --verbose -h --help"; scene="$sc/small.yaml" ;;
check)   flags="-o --output -s --set -q --quiet -v --verbose -h --help"; scene="$sc/small.yaml" ;;
compare) flags="-o --output -s --set -q --quiet -v --verbose -h --help"; scene="$sc/small.yaml" ;;
plot)    flags="-o --output -q --quiet -v --verbose -h --help"; scene="" ;;
study)   flags="-o --output -s --set --quick -j --jobs -q --quiet -v --verbose -h --help"; scene="$sc/small.yaml" ;;
nip)     flags="--radius --json -s --set -v --verbose -h --help"; scene="$sc/contact.yaml --radius 0.3" ;;
sweep)   flags="--vary --sample -o --output --csv --threads -s --set --profiles -q --quiet -v --verbose -h --help"
         scene="$sc/small.yaml --vary winding.tension=100:200:2" ;;
*) fail "unknown command $cmd" ;;
esac

run "$bin" help "$cmd"; [ "$got" -eq 0 ] || fail "help $cmd: exit $got"
help_text="$out"
has "^usage: reelsim $cmd "
for flag in $flags; do
  printf '%s\n' "$help_text" | grep -Eq -- "(^|[ ,[])$flag([] ,=]|$)" || fail "help $cmd lacks $flag"
done
for how in --help -h; do
  run "$bin" "$cmd" $how; [ "$got" -eq 0 ] || fail "$cmd $how: exit $got"
  [ "$out" = "$help_text" ] || fail "'$cmd $how' differs from 'help $cmd'"
done

run "$bin" "$cmd" --frobnicate $scene
[ "$got" -eq 2 ] || fail "$cmd --frobnicate: exit $got, expected 2"
has "reelsim: $cmd: unknown option '--frobnicate'"

if [ -n "$scene" ]; then
  for form in "--set numerics.rtol=abc" "--set=numerics.rtol=abc" "-s numerics.rtol=abc"; do
    run "$bin" "$cmd" $scene $form
    [ "$got" -eq 2 ] || fail "$cmd $form: exit $got, expected 2"
    has "reelsim: --set numerics\.rtol=abc: not a number \(got 'abc'\)"
  done
  [ -z "$(ls -A)" ] || { ls -la; fail "a refused command left files"; }
fi
echo PASS

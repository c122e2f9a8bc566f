# bash.sh: editors/bash/scn, the bash completion: it parses (bash -n), registers _scn for
# scn, and completes commands, options, the values of choices and file names filtered by
# what each argument takes; it knows every command of `scn --help` and every option of each
# usage line, and scn knows every option it offers.
. "$SCN_SRCDIR/tests/lib.sh"

command -v bash >/dev/null || { echo "SKIP: bash is not installed"; exit 77; }
completion=$SCN_SRCDIR/editors/bash/scn
LC_ALL=C # the order of the sorted replies below
export LC_ALL

expect_status 0 bash -n "$completion"
expect_status 0 bash --norc --noprofile -c '. "$1" && complete -p scn' bash "$completion"
only_line "$work/out" 'complete -F _scn scn'

# offers WORD...: what the completion offers for the command line WORD..., the last word
# being the one completed: the sorted replies on one line
cat >"$work/offers.bash" <<'EOF'
. "$1" || exit 1
shift
COMP_WORDS=("$@")
COMP_CWORD=$(($# - 1))
_scn
printf '%s\n' "${COMPREPLY[@]}" | sort | tr '\n' ' ' | sed 's/ $//'
EOF
offers() {
	bash --norc --noprofile "$work/offers.bash" "$completion" "$@"
}

# expect_offers WANT WORD...: the completion offers WANT for WORD...
expect_offers() {
	want=$1
	shift
	got=$(offers "$@" 2>"$work/err")
	[ "$got" = "$want" ] || fail "'$*<TAB>' offers '$got', expected '$want'"
	[ -s "$work/err" ] && { fail "'$*<TAB>' printed:"; cat "$work/err"; }
}

cd "$work" || exit 99
expect_offers 'render' scn re
expect_offers '--help --version -h check converge diff help merge pov render' scn ''
expect_offers 'check converge' scn help c
expect_offers '' scn help render ''
expect_offers '--seed --stats' scn render --s
expect_offers '--dump --help -h' scn check -
expect_offers '--no-pov' scn converge x.scn --no
expect_offers 'center grid jittered poisson random' scn render x.scn -p ''
expect_offers 'bvh grid none' scn render --accel ''
expect_offers '16 8' scn render --bit-depth ''
expect_offers 'linear linear,srgb srgb srgb,linear' scn diff --ppm ''
# --opt=VALUE, which bash splits at the '='
expect_offers 'bvh grid none' scn render --accel =
expect_offers 'grid' scn render --accel = g
# a number: nothing to offer, not the files
expect_offers '' scn render -s ''
expect_offers '' scn diff a.png b.png --max-rmse ''
expect_offers '' scn frobnicate ''

# file names, by extension in any case, and the folders
mkdir sub
touch a.scn B.SCN 'my scene.scn' c.png d.EXR e.ppm f.pov g.svg h.csv notes.txt
expect_offers 'B.SCN a.scn my scene.scn sub' scn render ''
expect_offers 'a.scn' scn check a
expect_offers 'B.SCN a.scn my scene.scn sub' scn converge -q ''
expect_offers 'c.png d.EXR e.ppm sub' scn diff ''
expect_offers 'c.png d.EXR e.ppm sub' scn diff c.png ''
expect_offers 'c.png d.EXR e.ppm sub' scn render a.scn -o ''
expect_offers 'f.pov sub' scn pov a.scn -o ''
expect_offers 'c.png d.EXR e.ppm sub' scn diff a.png b.png --heatmap ''
expect_offers 'c.png d.EXR e.ppm sub' scn converge a.scn --reference ''
expect_offers 'g.svg sub' scn converge a.scn --plot ''
expect_offers 'h.csv sub' scn converge a.scn --csv ''

# the commands are those of `scn --help`
expect_status 0 "$SCN" --help
commands=$(sed -n 's/^  scn \([a-z][a-z]*\) .*/\1/p' "$work/out" | sort | tr '\n' ' ')
[ -n "$commands" ] || fail "no commands in 'scn --help'"
[ "$(offers scn '' | tr ' ' '\n' | grep -v -e '^-' -e '^help$' | tr '\n' ' ')" = "$commands" ] ||
	fail "the completion's commands ($(offers scn '')) are not those of 'scn --help' ($commands)"

# a rejected option says so, as the checks below expect
expect_status 2 "$SCN" render --no-such-option
expect_grep "$work/err" "(unknown|unrecognized) option"
for cmd in $commands; do
	options=$(offers scn "$cmd" -)
	# every option of the usage line (up to the first empty line of `scn help CMD`)
	expect_status 0 "$SCN" help "$cmd"
	for opt in $(sed '/^$/q' "$work/out" | grep -oE '[[ |]--?[A-Za-z][-A-Za-z]*' | cut -c2- | sort -u); do
		case " $options " in
		*" $opt "*) ;;
		*) fail "'scn $cmd $opt' is in the usage line but the completion does not offer it" ;;
		esac
	done
	# and scn knows each option offered
	for opt in $options; do
		"$SCN" "$cmd" "$opt" </dev/null >/dev/null 2>"$work/err"
		grep -Eq "(unknown|unrecognized) option" "$work/err" &&
			fail "the completion offers 'scn $cmd $opt', which scn rejects: $(cat "$work/err")"
	done
done
finish

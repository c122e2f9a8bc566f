# options.sh: the GNU conventions of every subcommand's options (--name=value, values
# glued to short options, bundled short options, abbreviated long names, '--' to end the
# options), the messages for options that are unknown, ambiguous, lack a value or have one
# they do not take, and the hints for POV-Ray's +X options.
. "$SCN_SRCDIR/tests/lib.sh"

cd "$work" || exit 99
cat >scene.scn <<'EOF'
camera { location <0, 1, -4>  look_at <0, 0.5, 0>  resolution 12, 9 }
light  { position <-3, 6, -4> }
plane  { <0, 1, 0>, 0 }
sphere { <0, 0.6, 0>, 0.6 }
EOF

# same_image NAME ARGS...: scn render with ARGS writes the same bytes as ref.ppm
"$SCN" render scene.scn -q -s 16 -p random --seed 5 -j 2 -o ref.ppm || fail "the reference render exited $?"
same_image() {
	what=$1
	shift
	rm -f got.ppm
	"$SCN" render "$@" >"$work/out" 2>"$work/err" || { fail "'render $*' exited $?"; cat "$work/err"; }
	cmp -s ref.ppm got.ppm || fail "$what: 'render $*' differs from the reference"
	[ -s "$work/err" ] && fail "$what: 'render $*' printed: $(cat "$work/err")"
}

# --- the GNU conventions ---
same_image "--seed=5" scene.scn -q -s 16 -p random --seed=5 -j 2 -o got.ppm
same_image "-s16" scene.scn -q -s16 -prandom --seed 5 -j2 -ogot.ppm
same_image "bundled -qj2" scene.scn -qj2 -s 16 -p random --seed 5 -o got.ppm
same_image "bundled -qs16, options first" -qs16 -p random --seed=5 -j 2 -o got.ppm scene.scn
same_image "abbreviated --se" scene.scn -q -s 16 -p random --se 5 -j 2 -o got.ppm
# '--' ends the options: a scene whose name starts with '-'
cp scene.scn ./-dash.scn
expect_status 0 "$SCN" check -- -dash.scn
only_line "$work/err" ""
"$SCN" render -q -s 16 -p random --seed 5 -j 2 -o got.ppm -- -dash.scn 2>"$work/err" ||
	fail "render -- -dash.scn exited $?"
cmp -s ref.ppm got.ppm || fail "render -- -dash.scn differs from the reference"
expect_status 0 "$SCN" pov -o - -- -dash.scn
expect_grep "$work/out" '^sphere'
usage_error "more than one scene given ('-q')" render -o got.ppm -- -dash.scn -q
# without '--', such a name is an option
usage_error "unknown option '-d' for check" check -dash.scn
# '-' alone is still standard input
expect_status 0 "$SCN" check -- - <scene.scn
# the other commands take the same forms
expect_status 0 "$SCN" diff --max-error=0 -q ref.ppm got.ppm
only_line "$work/out" ""
expect_status 0 "$SCN" diff --ppm=linear --max-rmse=0 ref.ppm got.ppm
expect_grep "$work/out" '^rmse 0 '
expect_status 0 "$SCN" render --help
expect_grep "$work/out" '^usage: scn render'
expect_status 0 "$SCN" check -h
expect_grep "$work/out" '^usage: scn check'

# --- bad options: the message names the option as written, status 2 ---
usage_error "unknown option '--bogus' for render" render scene.scn --bogus
usage_error "unknown option '--bogus' for render" render scene.scn --bogus=3
usage_error "unknown option '-x' for render" render scene.scn -qx
usage_error "unknown option '-x' for render" render scene.scn -xq
usage_error "unknown option '-x' for pov" pov scene.scn -x
usage_error "unknown option '--sed' for render; did you mean '--seed'?" render scene.scn --sed 5
usage_error "unknown option '--heatmp' for diff; did you mean '--heatmap'?" diff a.png b.png --heatmp=h.png
usage_error "unknown option '--dumb' for check; did you mean '--dump'?" check --dumb scene.scn
usage_error "ambiguous option '--s' for render (--seed, --stats)" render scene.scn --s
usage_error "ambiguous option '--max' for diff (--max-rmse, --max-error, --max-mean, --max-off)" diff a b --max=1
usage_error "option '--seed' needs a value" render scene.scn --seed
usage_error "option '-s' needs a value" render scene.scn -qs
usage_error "option '--stats' takes no value" render scene.scn --stats=yes
usage_error "option '--help' takes no value" render --help=me
usage_error "bad value 'x' for --seed (a whole number in range)" render scene.scn --seed=x
usage_error "bad value '0' for -s (a whole number in range)" render scene.scn -s0
usage_error "bad value '0' for --budget (seconds, a positive number)" converge scene.scn --budget=0
usage_error "option '--reference' needs a value" converge scene.scn --reference

# --- POV-Ray's options: an operand that starts with '+' and names no file gets the
# equivalent option of the command, or where to look ---
# pov_generic CMD ARG OPERANDS...
pov_generic() {
	cmd=$1 arg=$2
	shift 2
	usage_error "'$arg' looks like a POV-Ray option, and POV-Ray's options are not scn's; see 'scn help $cmd'" \
		"$cmd" "$@" "$arg"
}
pov_equivalent() {
	usage_error "'$2' looks like a POV-Ray option; scn $1's equivalent is $3" "$1" scene.scn "$2"
}
pov_equivalent render +W320 "-W 320"
pov_equivalent render +H240 "-H 240"
pov_equivalent render +w64 "-W 64"
pov_equivalent render +W "-W WIDTH"
pov_equivalent render +Oout.png "-o out.png"
pov_equivalent render +A0.3 "-s SAMPLES (and -p PATTERN)"
pov_equivalent render +AM2 "-s SAMPLES (and -p PATTERN)"
pov_equivalent render +R3 "-s SAMPLES (and -p PATTERN)"
pov_equivalent render +J "-p jittered"
pov_equivalent render +WT4 "-j 4"
pov_equivalent render +SR10 "--region X0,Y0,X1,Y1"
pov_equivalent render +FN16 "-o OUT (.png, .exr or .ppm) and --bit-depth 8|16"
pov_generic pov +FN16 scene.scn
pov_equivalent render +Iscene.pov "the scene's name alone: scene.pov"
pov_equivalent converge +W320 "-W 320"
pov_equivalent converge +WT2 "-j 2"
pov_equivalent pov +Ox.pov "-o x.pov"
pov_generic render +Q9 scene.scn
pov_generic render +D scene.scn
pov_generic render +WL2 scene.scn
pov_generic converge +Oout.png scene.scn
pov_generic check +W320 scene.scn
pov_generic diff +A0.3 a.png b.png
# before the scene too, and before counting the scenes, and with no scene at all
usage_error "'+W320' looks like a POV-Ray option; scn render's equivalent is -W 320" render +W320
usage_error "'+W320' looks like a POV-Ray option; scn render's equivalent is -W 320" render +W320 scene.scn
# a file whose name starts with '+' is a file
cp scene.scn ./+W320
expect_status 0 "$SCN" check +W320
usage_error "more than one scene given ('+W320')" render scene.scn +W320
finish

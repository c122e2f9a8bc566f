#!/bin/sh
# fuzz.sh: `make fuzz`: builds the libFuzzer harnesses with clang (whatever CC the
# main build uses) and runs each for FUZZ_SECONDS. tests/fuzz/local.mk passes the
# sources, flags and libraries in the environment; see there. A finding (crash, hang,
# leak, out-of-memory) is saved under tests/fuzz/findings/HARNESS/ in the build tree and
# fails the run. New inputs that reach new code go to tests/fuzz/work/HARNESS/ there;
# the seeds in the source tree are only read.
set -eu

: "${FUZZ_CC:=clang}" "${FUZZ_SECONDS:=60}" "${FUZZ_TARGETS:=scene mesh png exr part}" "${FUZZ_OPTIONS:=}"
: "${FUZZ_SOURCES:?}" "${FUZZ_LIB_CFLAGS?}" "${FUZZ_LIBS:?}"
top_srcdir=${top_srcdir:?} top_builddir=${top_builddir:?}
# clang is needed for this target only, so it is installed here and not by README's
# first command
if ! command -v "$FUZZ_CC" >/dev/null 2>&1 && [ "$FUZZ_CC" = clang ] && command -v apt-get >/dev/null; then
	sudo=
	[ "$(id -u)" = 0 ] || sudo=sudo
	echo "fuzz.sh: installing clang, which has libFuzzer"
	$sudo apt-get install -y clang
fi
if ! command -v "$FUZZ_CC" >/dev/null 2>&1; then
	echo "fuzz.sh: $FUZZ_CC not found; the fuzz target needs clang with libFuzzer" >&2
	exit 1
fi

out=$top_builddir/tests/fuzz
obj=$out/obj
mkdir -p "$obj"
# FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION (the fuzzing world's convention): limits that
# would let one input run past the 10 s timeout are lower (lang/eval.h)
flags="-g -O1 -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all \
-std=c11 -Wall -Wextra -ffp-contract=off -pthread -D_XOPEN_SOURCE=700 -DFUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION \
-I$top_builddir -I$top_srcdir/tests/fuzz $FUZZ_LIB_CFLAGS"

# The libraries, compiled again with the sanitizers and coverage (only what changed). A
# header newer than the last library may change a structure that objects built before it
# lay out otherwise, and mixed layouts make false findings: then every object is rebuilt.
if [ -f "$obj/libscn.a" ] &&
	[ -n "$(find "$top_srcdir/lang" "$top_srcdir/render" "$top_srcdir/src" "$top_builddir/lang" \
		"$top_builddir/config.h" -name '*.h' -newer "$obj/libscn.a" 2>/dev/null | head -n 1)" ]; then
	rm -f "$obj"/*.o
fi
objs=
for s in $FUZZ_SOURCES; do
	case $s in
	*.c) ;;
	*.l|*.y) s=${s%.?}.c ;;   # flex and bison output, made by the main build
	*) continue ;;
	esac
	src=$top_builddir/$s
	[ -f "$src" ] || src=$top_srcdir/$s
	o=$obj/$(echo "$s" | tr / _ | sed 's/\.c$/.o/')
	if [ ! -f "$o" ] || [ "$src" -nt "$o" ] || [ "$0" -nt "$o" ]; then
		echo "  FUZZCC   $s"
		$FUZZ_CC $flags -fsanitize=fuzzer-no-link -c "$src" -o "$o.$$"
		mv "$o.$$" "$o"        # whole, should another run be linking beside this one
	fi
	objs="$objs $o"
done
rm -f "$obj/libscn.a.$$"
ar cr "$obj/libscn.a.$$" $objs
mv "$obj/libscn.a.$$" "$obj/libscn.a"

# max_len per format: enough for the seeds and a little more, small enough to stay fast
max_len() {
	case $1 in
	scene) echo 8192 ;;
	mesh) echo 4096 ;;
	png) echo 4096 ;;
	exr|part) echo 8192 ;;
	esac
}

# Seeds that live elsewhere in the tree, copied (the mesh files behind the byte that
# picks their reader, see fuzz_mesh.c) rather than kept twice in the repository.
seed() {
	rm -rf "$out/seed/$1"
	mkdir -p "$out/seed/$1"
	case $1 in
	scene)
		for f in "$top_srcdir"/examples/*.scn "$top_srcdir"/tests/*/*.scn; do
			cp "$f" "$out/seed/scene/$(echo "${f#"$top_srcdir"/}" | tr / _)"
		done ;;
	mesh)
		for f in "$top_srcdir"/tests/unit/meshes/*.ply "$top_srcdir"/examples/*.ply; do
			{ printf 0; cat "$f"; } >"$out/seed/mesh/$(basename "$f")"
		done
		for f in "$top_srcdir"/tests/unit/meshes/*.obj; do
			{ printf 1; cat "$f"; } >"$out/seed/mesh/$(basename "$f")"
		done ;;
	esac
}

# The front end's dictionary: its keywords and built-in functions, read from their
# tables so that it never falls behind them, its punctuation, and the fragments that
# nest objects in a CSG (a member's block inside the CSG's, a for loop of members), that
# define and call functions and macros, branch and index, the surfaces' blocks and names
# (which are not keywords), and the lights' and camera's blocks.
scene_dict() {
	sed -n '/^static const char \*const names/,/^};/p' "$top_srcdir/lang/keywords.c" |
		grep -o '"[a-z_]*"'
	grep -o '{ "[a-z0-9]*", [0-9]' "$top_srcdir/lang/builtins.c" | grep -o '"[a-z0-9]*"'
	for t in '+' '-' '*' '/' '=' '{' '}' '<' '>' '(' ')' ',' '..' '.x' '.y' '.z' '//' '/*' '*/' '"' '1e308' '-0' \
		'0.5' '1e-9' ' { sphere { 0, 1 } ' ' { box { 0, 1 } } ' 'for i in 0 .. 3 { ' '<0, 1, 0>' \
		'==' '!=' '<=' '>=' '?' ':' '[' ']' '[]' ' ? 1 : 0' 'def f(x) = x * 2 ' 'def m(p) { sphere { p, 1 } } ' \
		'm(<0, 0, 0>) ' 'if 1 < 2 { ' ' } else { ' ' } else if ' 'for x in [1, 2, 3] { ' '"a" + str(1)' 'xs[0]' \
		'diffuse pattern { ' 'diffuse image { "' 'normal { ' 'colors [[0, <1, 0, 0>], [1, 1]]' 'gradient <1, 0, 0>' \
		'marble' 'wood' 'bozo' 'granite' 'agate' 'spotted' 'leopard' 'onion' 'radial' 'bumps' 'dents' 'ripples' \
		'waves' 'wrinkles' 'map uv' 'map spherical' 'map cylindrical' 'interpolate bilinear' 'uvs { ' \
		' area { <1, 0, 0>, <0, 0, 1>, 4, 4  jitter } ' ' spotlight { point_at <0, 0, 0> } ' ' fog { distance 5 } ' \
		' aperture 0.5  focal_point <0, 0, 2> '; do
		printf '"%s"\n' "$(printf %s "$t" | sed 's/[\\"]/\\&/g')"
	done
}

# The harnesses' temporary files go in the build tree, where a crash leaves them, in a
# directory of this run's own: another run may be going on beside it.
mkdir -p "$out/tmp"
TMPDIR=$(mktemp -d "$out/tmp/run.XXXXXX")
export TMPDIR
# assimp's known leak: tests/fuzz/lsan.supp says why its own file
lsan="suppressions=$top_srcdir/tests/fuzz/lsan.supp:print_suppressions=0"

status=0
for h in $FUZZ_TARGETS; do
	bin=$out/fuzz_$h
	echo "  FUZZLD   tests/fuzz/fuzz_$h"
	$FUZZ_CC $flags -fsanitize=fuzzer "$top_srcdir/tests/fuzz/fuzz_$h.c" \
		"$top_srcdir/tests/fuzz/fuzz_file.c" "$obj/libscn.a" $FUZZ_LIBS -lm -o "$bin.$$"
	mv "$bin.$$" "$bin"
	[ "$FUZZ_SECONDS" = 0 ] && continue     # build only
	mkdir -p "$out/work/$h" "$out/findings/$h"
	seed "$h"
	dict=
	if [ "$h" = scene ]; then
		scene_dict >"$out/scene.dict"
		dict=-dict=$out/scene.dict
	fi
	echo "fuzz.sh: fuzz_$h for $FUZZ_SECONDS s"
	LSAN_OPTIONS=$lsan nice -n 19 "$bin" -max_total_time="$FUZZ_SECONDS" -rss_limit_mb=2048 -timeout=10 \
		-max_len="$(max_len "$h")" -print_final_stats=1 $dict \
		-artifact_prefix="$out/findings/$h/" $FUZZ_OPTIONS \
		"$out/work/$h" "$top_srcdir/tests/fuzz/corpus/$h" "$out/seed/$h" </dev/null || status=1
done
rm -rf "$TMPDIR"
exit $status

# portable.sh: a part rendered on a CPU without AVX equals one rendered with it. scn's
# renderer is compiled with -mavx where the machine has AVX (configure's AVX_CFLAGS);
# scn_portable is the same sources without it, and runs with glibc's AVX, AVX2, FMA and
# FMA4 masked (GLIBC_TUNABLES), so that libm's functions take their SSE2 variants as on
# such a CPU. Whole images and --tile parts of scenes that reach each vector path
# (spheres, a mesh's triangle packets, textures, an area light, focal blur) must have the
# same bytes from both, and parts of one must merge with parts of the other.
# The mask matters: on glibc 2.36, libm's FMA and SSE2 variants of exp, log, pow, sin, cos,
# tan, atan and atan2 differ in the last bit for about 1 argument in 1500; here no such
# difference reaches a pixel (the film is single precision), which is evidence for these
# scenes, not a proof for every scene.
. "$SCN_SRCDIR/tests/lib.sh"

portable=$(dirname "$SCN")/tests/cpu/scn_portable
[ -x "$portable" ] || { echo "no $portable"; exit 99; }
# glibc 2.33 and later name the features without the _Usable of older releases, whose
# names they ignore without a word (ld.so --list-diagnostics shows the masks taking effect)
mask=glibc.cpu.hwcaps=-AVX2,-AVX,-FMA,-FMA4
cd "$work" || exit 99
# On a machine with AVX the mask must take effect, or this compares the AVX paths twice
ldso=/lib64/ld-linux-x86-64.so.2
if grep -qw avx /proc/cpuinfo 2>/dev/null && "$ldso" --list-diagnostics >/dev/null 2>&1; then
	"$ldso" --list-diagnostics | grep 'cpu_features.*active' >features
	GLIBC_TUNABLES=$mask "$ldso" --list-diagnostics | grep 'cpu_features.*active' >masked
	cmp -s features masked && fail "GLIBC_TUNABLES=$mask left glibc's CPU features as they were"
fi

cat >balls.scn <<'EOF2'
camera { location <0, 1.2, -5>  look_at <0, 0.5, 0>  resolution 48, 36 }
light  { position <-3, 6, -4> }
samples 4
plane  { <0, 1, 0>, 0  material { diffuse checker(<0.9, 0.9, 0.9>, <0.2, 0.2, 0.3>, 0.5)  reflect 0.2 } }
sphere { <0, 0.8, 0>, 0.8  material { diffuse <0.8, 0.3, 0.2>  specular 0.5  shininess 60 } }
sphere { <1, 0.3, -1>, 0.3  material { diffuse 0.1  transmit 0.9  ior 1.5  fresnel } }
torus  { 0.5, 0.1  rotate <60, 0, 0>  translate <-1.3, 0.5, -0.5>  material { diffuse <0.2, 0.6, 0.3> } }
EOF2
cat >area.scn <<'EOF2'
camera { location <0, 2, -5>  look_at <0, 0.5, 0>  resolution 48, 36 }
light  { position <-1, 4, -2>  area { <1, 0, 0>, <0, 0, 1>, 4, 4  jitter } }
samples 4
plane  { <0, 1, 0>, 0 }
sphere { <0, 0.7, 0>, 0.7  material { diffuse <0.7, 0.7, 0.9> } }
box    { <0.8, 0, -0.5>, <1.4, 0.6, 0.1> }
EOF2

# both NAME SCENE ARGS...: renders SCENE with ARGS with scn and with scn_portable, each
# into a 16-bit PNG, a half and a float EXR (NAME-avx-png16.png, NAME-sse-half.exr, ...),
# and compares them
both() {
	name=$1 scene=$2
	shift 2
	for f in "png16.png --bit-depth 16" "half.exr" "float.exr --float"; do
		file=${f%% *} opts=${f#* }
		[ "$opts" = "$f" ] && opts=
		# shellcheck disable=SC2086 # options
		"$SCN" render "$scene" -q "$@" $opts -o "$name-avx-$file" || fail "scn render $scene $* $opts exited $?"
		# shellcheck disable=SC2086
		GLIBC_TUNABLES=$mask "$portable" render "$scene" -q "$@" $opts -o "$name-sse-$file" ||
			fail "scn_portable render $scene $* $opts exited $?"
		same_bytes "$name-avx-$file" "$name-sse-$file" "$name as $file"
	done
}

# parts NAME SCENE ARGS...: SCENE's three parts with each program, the same bytes; part
# 1 of scn_portable merged with parts 0 and 2 of scn, and the other way round, give the
# whole's float EXR (both's NAME-avx-float.exr)
parts() {
	name=$1 scene=$2
	shift 2
	for k in 0 1 2; do
		"$SCN" render "$scene" -q "$@" --tile $k/3 -o "$name-avx-$k.exr" || fail "scn render $scene --tile $k/3 exited $?"
		GLIBC_TUNABLES=$mask "$portable" render "$scene" -q "$@" --tile $k/3 -o "$name-sse-$k.exr" ||
			fail "scn_portable render $scene --tile $k/3 exited $?"
		same_bytes "$name-avx-$k.exr" "$name-sse-$k.exr" "$name part $k of 3"
	done
	"$SCN" merge -q "$name-avx-0.exr" "$name-sse-1.exr" "$name-avx-2.exr" --float -o "$name-mixed.exr" ||
		fail "merge of $name's mixed parts exited $?"
	same_bytes "$name-avx-float.exr" "$name-mixed.exr" "$name's parts of both programs merged"
	GLIBC_TUNABLES=$mask "$portable" merge -q "$name-sse-0.exr" "$name-avx-1.exr" "$name-sse-2.exr" --float \
		-o "$name-mixed2.exr" || fail "scn_portable merge of $name's mixed parts exited $?"
	same_bytes "$name-avx-float.exr" "$name-mixed2.exr" "$name's parts of both programs merged by scn_portable"
}

for s in balls area; do
	both "$s" $s.scn
	parts "$s" $s.scn
done
for s in "bunny $SCN_SRCDIR/examples/bunny.scn -W 48 -H 36" \
	"textures $SCN_SRCDIR/examples/textures.scn -W 64 -H 48 -s 4" \
	"blur $SCN_SRCDIR/tests/cli/focal_blur.scn -W 48 -H 36"; do
	# shellcheck disable=SC2086 # a name, a scene and options
	both $s
	# shellcheck disable=SC2086
	parts $s
done
finish

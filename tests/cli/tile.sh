# tile.sh: `scn render --tile K/N` and `scn merge` (LANGUAGE.md section 13): the parts of
# any split, merged in any order, have the bytes of one render of the whole in every
# format, for every sample pattern, adaptive sampling, a mesh and a --region; merge
# refuses a missing part, a part twice, a part of another scene, of a scene whose image
# map changed, of other options or another split, and a file that is no part, writing
# nothing; the usage errors and the parts' default names.
. "$SCN_SRCDIR/tests/lib.sh"

cd "$work" || exit 99
# 64 rows, so that a split into 64 has parts of one row
cat >balls.scn <<'EOF'
camera { location <0, 1.2, -5>  look_at <0, 0.5, 0>  resolution 24, 64 }
light  { position <-3, 6, -4> }
skybox { zenith <0.2, 0.3, 0.7>  horizon <0.8, 0.8, 0.9> }
plane  { <0, 1, 0>, 0  material { diffuse checker(<0.9, 0.9, 0.9>, <0.2, 0.2, 0.3>, 0.5)  reflect 0.2 } }
sphere { <0, 0.8, 0>, 0.8  material { diffuse <0.8, 0.3, 0.2>  specular 0.5  shininess 60 } }
sphere { <1, 0.3, -1>, 0.3  material { diffuse 0.1  transmit 0.9  ior 1.5 } }
EOF
sed 's/^camera.*/&\nsamples { count 16  target_error 0.02 }/' balls.scn >adaptive.scn

# whole NAME SCENE ARGS...: renders SCENE with ARGS into NAME.png, NAME-16.png,
# NAME.exr, NAME-float.exr and NAME.ppm
whole() {
	name=$1 scene=$2
	shift 2
	for f in "$name.png" "$name-16.png --bit-depth 16" "$name.exr" "$name-float.exr --float" "$name.ppm"; do
		# shellcheck disable=SC2086 # $f is a name and its options
		"$SCN" render "$scene" -q "$@" -o $f || fail "render $scene $* -o $f exited $?"
	done
}

# split NAME N SCENE ARGS...: renders SCENE with ARGS in N parts, merges them into the
# five formats, and compares each with whole NAME's
split() {
	name=$1 n=$2 scene=$3
	shift 3
	rm -f part-*.exr
	parts=
	k=0
	while [ $k -lt "$n" ]; do
		"$SCN" render "$scene" -q "$@" --tile $k/"$n" -o part-$k.exr || fail "render $scene $* --tile $k/$n exited $?"
		parts="$parts part-$k.exr"
		k=$((k + 1))
	done
	for f in "$name.png" "$name-16.png --bit-depth 16" "$name.exr" "$name-float.exr --float" "$name.ppm"; do
		out=merged.${f#*.}
		rm -f "${out%% *}"
		# shellcheck disable=SC2086 # lists of names and options
		"$SCN" merge -q $parts -o $out >"$work/out" 2>"$work/err" || { fail "merge into $f exited $?"; cat "$work/err"; }
		same_bytes "${f%% *}" "${out%% *}" "$name in $n parts, merged as $f"
	done
}

for p in "center -s 1" "grid -s 4" "random -s 4" "jittered -s 4" "poisson -s 4"; do
	set -- $p
	whole "$1" balls.scn -p "$@"
	for n in 1 2 7 64; do
		split "$1" $n balls.scn -p "$@"
	done
done
whole adaptive adaptive.scn
for n in 1 2 7 64; do
	split adaptive $n adaptive.scn
done
# (part 39 of 64 is a chunk whose zlib bytes are exactly as many as its raw bytes, which
# OpenEXR up to 3.4.7 writes wrongly: exr.c's compress_chunk)
bunny=$SCN_SRCDIR/examples/bunny.scn
whole bunny "$bunny" -W 32 -H 64 -s 1
for n in 1 2 7 64; do
	split bunny $n "$bunny" -W 32 -H 64 -s 1
done
# a --region is the image that is split
whole region balls.scn -s 4 --region 3,10,21,50
for n in 1 3 40; do
	split region $n balls.scn -s 4 --region 3,10,21,50
done
# the split can fail: parts that are not the whole's bands do not merge into its bytes
cmp -s center.png grid.png && fail "center and grid renders are the same image"

# --- in any order, the same bytes and the same estimate ---
for k in 0 1 2 3 4; do
	"$SCN" render balls.scn -q -s 4 --tile $k/5 || fail "render --tile $k/5 exited $?"
done
"$SCN" merge balls-3-of-5.exr balls-0-of-5.exr balls-4-of-5.exr balls-2-of-5.exr balls-1-of-5.exr -o shuffled.png \
	2>"$work/err" || fail "merge in shuffled order exited $?"
same_bytes jittered.png shuffled.png "parts merged in shuffled order"
# wide enough (8192 pixels) that the probes are a share of the pixels, which is the
# whole image's in each part, not the part's own
for k in 0 1 2 3 4; do
	"$SCN" render balls.scn -q -s 4 -W 128 --tile $k/5 -o wide-$k.exr || fail "render -W 128 --tile $k/5 exited $?"
done
"$SCN" merge wide-4.exr wide-2.exr wide-0.exr wide-3.exr wide-1.exr -o wide.png 2>"$work/err" ||
	fail "merge of the wide parts exited $?"
"$SCN" render balls.scn -s 4 -W 128 -o wide-whole.png 2>"$work/whole.err" || fail "render -W 128 exited $?"
same_bytes wide-whole.png wide.png "the wide parts merged in shuffled order"
est=$(sed -n 's/.*; estimated RMSE \(.*\)$/\1/p' "$work/whole.err")
[ -n "$est" ] || fail "the whole render gave no estimate"
only_line "$work/err" "scn: wrote wide.png: 128 x 64 from 5 parts; estimated RMSE $est"

# --- default names: K padded to the digits of N - 1 ---
"$SCN" render balls.scn -q --tile 3/16 || fail "render --tile 3/16 exited $?"
[ -f balls-03-of-16.exr ] || fail "--tile 3/16 did not write balls-03-of-16.exr"
"$SCN" render balls.scn -q --tile 3/10 || fail "render --tile 3/10 exited $?"
[ -f balls-3-of-10.exr ] || fail "--tile 3/10 did not write balls-3-of-10.exr"

# --- refusals: one line naming the files, exit 3, nothing written ---
# refused WANT ARGS...: scn merge ARGS -o refused.png exits 3 with the one line WANT
refused() {
	line=$1
	shift
	expect_status 3 "$SCN" merge "$@" -o refused.png
	only_line "$work/err" "scn: error: $line"
	[ -e refused.png ] && fail "a refused merge wrote refused.png"
	no_temp "a refused merge"
}
refused "part 2 of 5 (rows 25 to 37) is missing" balls-0-of-5.exr balls-1-of-5.exr balls-3-of-5.exr balls-4-of-5.exr
refused "part 4 of 5 (rows 51 to 63) is missing" balls-0-of-5.exr balls-1-of-5.exr balls-2-of-5.exr balls-3-of-5.exr
cp balls-1-of-5.exr again.exr
refused "'balls-1-of-5.exr' and 'again.exr' are both part 1 of 5" balls-0-of-5.exr balls-1-of-5.exr again.exr \
	balls-2-of-5.exr balls-3-of-5.exr balls-4-of-5.exr
sed 's/0.8, 0.3, 0.2/0.8, 0.3, 0.25/' balls.scn >edited.scn
"$SCN" render edited.scn -q -s 4 --tile 2/5 -o edited.exr || fail "render edited.scn exited $?"
refused "'balls-0-of-5.exr' and 'edited.exr' are parts of different scenes (the scenes or the files they read differ)" \
	balls-0-of-5.exr balls-1-of-5.exr edited.exr balls-3-of-5.exr balls-4-of-5.exr
"$SCN" render balls.scn -q -s 9 --tile 2/5 -o samples.exr || fail "render -s 9 exited $?"
refused "'balls-0-of-5.exr' and 'samples.exr' are parts of renders with different settings ('24 x 64; 4 samples, pattern jittered, seed 0; max_depth 5; accel bvh' and '24 x 64; 9 samples, pattern jittered, seed 0; max_depth 5; accel bvh')" \
	balls-0-of-5.exr balls-1-of-5.exr samples.exr balls-3-of-5.exr balls-4-of-5.exr
"$SCN" render balls.scn -q -s 4 --seed 7 --tile 2/5 -o seed.exr || fail "render --seed 7 exited $?"
refused "'balls-0-of-5.exr' and 'seed.exr' are parts of renders with different settings ('24 x 64; 4 samples, pattern jittered, seed 0; max_depth 5; accel bvh' and '24 x 64; 4 samples, pattern jittered, seed 7; max_depth 5; accel bvh')" \
	balls-0-of-5.exr balls-1-of-5.exr seed.exr balls-3-of-5.exr balls-4-of-5.exr
refused "'balls-0-of-5.exr' and 'balls-03-of-16.exr' are parts of different splits (into 5 and 16 parts)" \
	balls-0-of-5.exr balls-03-of-16.exr
refused "'jittered.exr': not a part of a --tile render (no scnPart attribute)" jittered.exr balls-0-of-5.exr
refused "cannot read 'jittered.png': not an OpenEXR file" jittered.png
refused "cannot read 'none.exr': No such file or directory" balls-0-of-5.exr none.exr
# a file the scene reads is part of what names it: the same scene with another image
cat >map.scn <<'EOF'
camera { location <0, 0, -3>  look_at <0, 0, 0>  resolution 16, 16 }
light  { position <0, 0, -5> }
box { <-1, -1, 0>, <1, 1, 0.1>  material { diffuse image { "map.png"  map planar  scale 2  translate <-1, -1, 0> } } }
EOF
cp "$SCN_SRCDIR/examples/picture.png" map.png
"$SCN" render map.scn -q --tile 0/2 || fail "render map.scn --tile 0/2 exited $?"
cp "$SCN_SRCDIR/examples/sky.png" map.png
"$SCN" render map.scn -q --tile 1/2 || fail "render map.scn --tile 1/2 exited $?"
refused "'map-0-of-2.exr' and 'map-1-of-2.exr' are parts of different scenes (the scenes or the files they read differ)" \
	map-0-of-2.exr map-1-of-2.exr

# --- usage errors ---
usage_error "bad --tile '1': not K/N" render balls.scn --tile 1
usage_error "bad --tile 'a/4': not K/N" render balls.scn --tile a/4
usage_error "bad --tile '4/4': K must be less than N (parts are numbered from 0)" render balls.scn --tile 4/4
usage_error "bad --tile '0/0': N must be at least 1" render balls.scn --tile 0/0
usage_error "--tile 0/65: 65 parts are more than the 64 rows of the image" render balls.scn --tile 0/65
usage_error "--tile 0/41: 41 parts are more than the 40 rows of the image" render balls.scn --tile 0/41 \
	--region 3,10,21,50
usage_error "--tile and --frames do not go together: render one frame per task with --frames F..F+1" \
	render balls.scn --tile 0/2 --frames 1..3
usage_error "--tile writes a 32-bit float OpenEXR part: 'part.png' must end in .exr" render balls.scn --tile 0/2 \
	-o part.png
usage_error "no output given (-o OUT)" merge balls-0-of-5.exr
usage_error "no parts given" merge -o x.png
usage_error "cannot tell the format of 'x.tif' (use .png, .exr or .ppm)" merge balls-0-of-5.exr -o x.tif
finish

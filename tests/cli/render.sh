# render.sh: `scn render` as LANGUAGE.md section 8 describes it: the same bytes whatever
# the thread count and for repeated runs (every sample pattern, PNG, EXR and PPM);
# --region is exactly a crop of the full image; output formats and their headers; exit
# statuses, messages and atomic output (a failed render leaves no file and never
# destroys an existing one); the default output name; --stats; scenes from stdin.
# Images are tiny so that the whole script takes about a second.
. "$SCN_SRCDIR/tests/lib.sh"

cd "$work" || exit 99

# spheres (one a mirror, one glass), a checkered floor, a light and a sky: every kind of ray
cat >scene.scn <<'EOF'
camera { location <0, 1.5, -6>  look_at <0, 1, 0>  fov 55  resolution 40, 30 }
light  { position <-4, 8, -6>  color <1, 1, 1> }
skybox { zenith <0.15, 0.35, 0.8>  horizon <0.75, 0.85, 1> }
material mirror { diffuse 0.05  specular 0.8  shininess 200  reflect 0.9 }
material glass  { diffuse 0  specular 0.5  shininess 300  reflect 0.1  transmit 0.9  ior 1.5 }
material floor  { diffuse checker(<0.9, 0.9, 0.9>, <0.8, 0.1, 0.1>, 1) }
plane  { <0, 1, 0>, 0  material floor }
sphere { <-1.2, 1, 1>, 1  material mirror }
sphere { <1.2, 1, -0.5>, 1  material glass }
sphere { <0, 0.3, -1.5>, 0.3 }
EOF

render() {
	"$SCN" render scene.scn --no-progress "$@" >"$work/out" 2>"$work/err"
}

# --- determinism: thread count, repeated runs, every pattern and format ---
for spec in "center 1" "grid 4" "random 4" "jittered 5" "poisson 7"; do
	set -- $spec
	pattern=$1 count=$2
	for ext in png exr ppm; do
		for j in 1 2 0; do
			render -p "$pattern" -s "$count" -j "$j" -o "det-$j.$ext" ||
				{ fail "render -p $pattern -s $count -j $j -o det-$j.$ext exited $?"; cat "$work/err"; }
		done
		same_bytes det-1.$ext det-2.$ext "$pattern $count, $ext, -j 1 against -j 2"
		same_bytes det-1.$ext det-0.$ext "$pattern $count, $ext, -j 1 against -j 0"
		render -p "$pattern" -s "$count" -j 2 -o "again.$ext"
		same_bytes det-2.$ext again.$ext "$pattern $count, $ext, two runs"
	done
	cp det-1.ppm "pattern-$pattern.ppm"
done
# the patterns do differ (anti-aliased edges), so the comparisons above compared something
cmp -s pattern-center.ppm pattern-grid.ppm && fail "grid 4 gives the same image as center"
cmp -s pattern-random.ppm pattern-jittered.ppm && fail "random 4 and jittered 5 give the same image"
# the seed reaches the random patterns, and the same seed gives the same image
render -p random -s 4 --seed 1 -o seed1.ppm
render -p random -s 4 --seed 2 -o seed2.ppm
render -p random -s 4 --seed 1 -j 1 -o seed1b.ppm
cmp -s seed1.ppm seed2.ppm && fail "--seed 1 and --seed 2 give the same random image"
same_bytes seed1.ppm seed1b.ppm "--seed 1 twice"
# a scene without triangles: brute force and the BVH see the same hits
render -s 4 -p grid --accel none -o none.ppm
render -s 4 -p grid --accel bvh -o bvh.ppm
same_bytes none.ppm bvh.ppm "--accel none against --accel bvh"
render -s 4 -p grid --accel grid --stats -o grid.ppm
same_bytes none.ppm grid.ppm "--accel none against --accel grid"
expect_grep "$work/err" ' build grid [0-9.]+s .*'
expect_grep "$work/err" '; grid [1-9][0-9]* x [1-9][0-9]* x [1-9][0-9]* cells, [1-9][0-9]* references$'

# --- --region: exactly the crop of the full image ---
header_len() {
	n=$(head -n 3 "$1" | wc -c)
	echo $((n))
}

# check_crop FULL CROP X0 Y0 X1 Y1 FULLWIDTH: CROP's pixel rows equal FULL's, byte for byte
check_crop() {
	hf=$(header_len "$1")
	hc=$(header_len "$2")
	w=$(($5 - $3))
	head -n 2 "$2" | tail -n 1 | grep -qx "$w $(($6 - $4))" ||
		fail "region $3,$4,$5,$6: header '$(head -n 2 "$2" | tail -n 1)'"
	y=$4
	while [ "$y" -lt "$6" ]; do
		dd if="$1" of=row.full bs=1 skip=$((hf + (y * $7 + $3) * 3)) count=$((w * 3)) 2>/dev/null
		dd if="$2" of=row.crop bs=1 skip=$((hc + (y - $4) * w * 3)) count=$((w * 3)) 2>/dev/null
		if ! cmp -s row.full row.crop; then
			fail "region $3,$4,$5,$6: row $y differs from the full image"
			break
		fi
		y=$((y + 1))
	done
	[ "$(wc -c <"$2")" -eq $((hc + w * ($6 - $4) * 3)) ] || fail "region $3,$4,$5,$6: wrong file size"
}

render -p jittered -s 5 -o full.ppm
for region in "8 5 37 29" "0 0 40 30" "39 29 40 30" "0 16 16 17" "15 0 33 30"; do
	set -- $region
	render -p jittered -s 5 -j 2 --region "$1,$2,$3,$4" -o crop.ppm ||
		{ fail "--region $1,$2,$3,$4 exited $?"; cat "$work/err"; continue; }
	check_crop full.ppm crop.ppm "$1" "$2" "$3" "$4" 40
done
render -p jittered -s 5 --region 0,0,40,30 -o crop.ppm
same_bytes full.ppm crop.ppm "--region of the whole image"

# --- a shadow ray along a seam of the BVH: a directional light straight down gives
# shadow rays the direction <-0, 1, -0>; from floor points at x = 0 exactly (the centre
# column of an odd width) they run in the plane where the ceiling mesh's two halves, and
# their boxes, meet. They must be blocked like their neighbours (the slab test once lost
# both boxes for a -0 component, and the centre column was lit).
cat >seam.scn <<'EOF'
camera { location <0, 1, -3> look_at <0, 0, 0> fov 60 resolution 41, 31 }
light { direction <0, -1, 0> }
plane { <0, 1, 0>, 0 }
mesh { vertices { <-4,2,-4>, <4,2,-4>, <4,2,4>, <-4,2,4>, <0,2,-4>, <0,2,4> }
       faces { <0,4,5>, <0,5,3>, <4,1,2>, <4,2,5> } }
EOF
"$SCN" render seam.scn --region 0,12,41,31 -o seam.ppm 2>"$work/err" || fail "seam.scn exited $?"
lit=$(dd if=seam.ppm bs=1 skip="$(header_len seam.ppm)" 2>/dev/null | od -An -v -tu1 | tr -s ' ' '\n' | grep -c '[1-9]')
[ "$lit" -eq 0 ] || fail "seam.scn: $lit bytes of the shadowed floor are lit"

# --- formats and their headers ---
render -o d8.png
[ "$(od -An -tx1 -N8 d8.png | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "d8.png is not a PNG"
[ "$(od -An -tu1 -j24 -N2 d8.png | tr -s ' ' | sed 's/^ //')" = "8 2" ] || fail "default PNG: not 8-bit RGB"
render --bit-depth 16 -o d16.png
[ "$(od -An -tu1 -j24 -N2 d16.png | tr -s ' ' | sed 's/^ //')" = "16 2" ] || fail "--bit-depth 16 PNG: not 16-bit RGB"
render --bit-depth 16 -o d16.ppm
[ "$(head -n 3 d16.ppm | tr '\n' ' ')" = "P6 40 30 65535 " ] || fail "--bit-depth 16 PPM header: $(head -n 3 d16.ppm | tr '\n' ' ')"
[ "$(wc -c <d16.ppm)" -eq $(($(header_len d16.ppm) + 40 * 30 * 6)) ] || fail "--bit-depth 16 PPM: wrong size"
[ "$(head -n 3 full.ppm | tr '\n' ' ')" = "P6 40 30 255 " ] || fail "PPM header: $(head -n 3 full.ppm | tr '\n' ' ')"
# EXR: the magic number, then the channel list's pixel type: 1 half, 2 float
exr_has() {
	od -An -tx1 -N400 "$1" | tr -d ' \n' | grep -q "$2"
}
render -o half.exr
render --float -o float.exr
for f in half.exr float.exr; do
	[ "$(od -An -tx1 -N4 $f | tr -d ' \n')" = 762f3101 ] || fail "$f lacks the OpenEXR magic number"
done
exr_has half.exr 6368616e6e656c73 || fail "half.exr has no channel list"
exr_has half.exr 420001000000 || fail "half.exr: channel B is not half"
exr_has half.exr 420002000000 && fail "half.exr: channel B is float"
exr_has float.exr 420002000000 || fail "float.exr (--float): channel B is not float"
exr_has float.exr 520002000000 || fail "float.exr (--float): channel R is not float"
# -W and -H override the scene's resolution
render -W 20 -H 10 -o small.ppm
[ "$(head -n 3 small.ppm | tr '\n' ' ')" = "P6 20 10 255 " ] || fail "-W 20 -H 10: $(head -n 3 small.ppm | tr '\n' ' ')"

# --- --stats ---
render --stats -j 1 -o stats.png
expect_grep "$work/err" '^time: parse [0-9.]+s  check [0-9.]+s  evaluate [0-9.]+s .* build bvh [0-9.]+s  render [0-9.]+s  write [0-9.]+s$'
expect_grep "$work/err" '^rays: +camera 1200 +shadow [1-9][0-9]* +reflection [1-9][0-9]* +refraction [1-9][0-9]* +total [0-9]+$'
expect_grep "$work/err" '^non-finite radiance values: 0$'
expect_grep "$work/err" '^evaluation: [1-9][0-9]* steps, 0 calls of functions and macros$'
grep '^rays:' "$work/err" >rays1
render --stats -j 2 -o stats.png
grep '^rays:' "$work/err" >rays2
same_bytes rays1 rays2 "--stats ray counts with -j 1 and -j 2"
# the evaluation's work: a macro that calls itself counts each call (1 + 2 + 4 + 8 = 15),
# and a function's calls too
printf 'def f(x) = x / 2\ndef tree(d) { sphere { <d, 0, 0>, f(1) }  if d > 0 { tree(d - 1)  tree(d - 1) } }\ntree(3)\n' \
	>"$work/calls.scn"
expect_status 0 "$SCN" render "$work/calls.scn" --stats -W 8 -H 8 -o "$work/calls.png" -q
expect_grep "$work/err" '^evaluation: [1-9][0-9]* steps, 30 calls of functions and macros$'
render -o plain.png
grep -Eq '^(time|rays):' "$work/err" && fail "a render without --stats printed statistics: $(cat "$work/err")"
render -q -o quiet.png
[ -s "$work/err" ] && fail "render -q printed: $(cat "$work/err")"
# the progress bar, asked for when standard error is not a terminal; -q silences it
render --progress -o progress.png
expect_grep "$work/err" '100%'
render --progress -q -o progress.png
[ -s "$work/err" ] && fail "-q did not silence --progress: $(cat "$work/err")"

# --- standard input ---
"$SCN" render - -o stdin.ppm -p jittered -s 5 <scene.scn 2>"$work/err" || fail "render - exited $?"
same_bytes full.ppm stdin.ppm "the scene from standard input"
printf 'sphere { <0,0,0>, -1 }\n' >bad-stdin.scn
expect_status 1 "$SCN" render - -o bad-stdin.png <bad-stdin.scn
expect_grep "$work/err" '^<stdin>:1:19: error:'
[ -e bad-stdin.png ] && fail "a scene with errors from stdin wrote its output"

# --- the default output name: the scene's name with .png, in the current directory ---
mkdir sub run
cp scene.scn sub/my.scene.scn
(cd run && "$SCN" render ../sub/my.scene.scn --no-progress 2>"$work/err") || fail "render without -o exited $?"
[ -f run/my.scene.png ] || fail "render without -o did not write my.scene.png in the current directory"
[ -e sub/my.scene.png ] && fail "render without -o wrote next to the scene"
same_bytes d8.png run/my.scene.png "the default output"

# --- bad command lines: status 2, a message, no output ---
for args in "-s 0" "-s abc" "-s 70000" "-s" "-p bogus" "-W 0" "-W abc" "-W 65537" "-H -1" "-d 0" "-d 257" \
	"-j -1" "--bit-depth 12" "--region 1,2,3" "--region 0,0,41,30" "--region 5,5,5,9" "--accel fast" \
	"-p grid -s 10" "-p center -s 4" "--bogus"; do
	set -- $args
	expect_status 2 "$SCN" render scene.scn -o usage.png "$@"
	[ -s "$work/err" ] || fail "'render $args' gave no message"
	grep -q '^usage: scn render' "$work/err" || fail "'render $args' did not show the usage"
	[ -e usage.png ] && { fail "'render $args' wrote its output"; rm -f usage.png; }
done
expect_status 2 "$SCN" render scene.scn -p grid -s 10 -o usage.png
expect_grep "$work/err" 'grid needs a square sample count.*10'
expect_status 2 "$SCN" render scene.scn -s 0 -o usage.png
expect_grep "$work/err" "bad value '0' for -s"
expect_status 2 "$SCN" render scene.scn -p bogus
expect_grep "$work/err" "unknown pattern 'bogus'"
expect_status 2 "$SCN" render scene.scn -W 0
expect_grep "$work/err" "bad value '0' for -W"
# an extension that names no format
expect_status 2 "$SCN" render scene.scn -o out.bmp
expect_grep "$work/err" "cannot tell the format of 'out.bmp'"
expect_status 2 "$SCN" render scene.scn -o noextension
[ -e out.bmp ] || [ -e noextension ] && fail "an unknown extension wrote a file"

# --- files that cannot be read or written: status 3 with the OS reason ---
expect_status 3 "$SCN" render missing.scn -o missing.png
expect_grep "$work/err" "cannot read 'missing.scn': No such file or directory"
expect_status 3 "$SCN" render scene.scn -o nodir/out.png
expect_grep "$work/err" "nodir/out.png.*No such file or directory"
[ -e nodir ] && fail "a missing output directory was created"
expect_status 3 "$SCN" render scene.scn -o scene.scn/out.png
expect_grep "$work/err" 'Not a directory'
mkdir isdir.png
expect_status 3 "$SCN" render scene.scn -o isdir.png
expect_grep "$work/err" 'Is a directory'
[ -d isdir.png ] || fail "the directory in the way was replaced"
no_temp "a failed rename"

# --- an existing output is never destroyed by a failed render ---
cp d8.png keep.png
cp d8.png keep.ppm
printf 'sphere { <0,0,0>, -1 }\n' >bad.scn
expect_status 1 "$SCN" render bad.scn -o keep.png
same_bytes d8.png keep.png "a scene error"
expect_status 1 "$SCN" render bad.scn -o new.png
[ -e new.png ] && fail "a scene with errors wrote its output"
expect_status 2 "$SCN" render scene.scn -p grid -s 10 -o keep.png
same_bytes d8.png keep.png "a bad sample count"
expect_status 2 "$SCN" render scene.scn --region 0,0,50,50 -o keep.png
same_bytes d8.png keep.png "a bad region"
# a write that fails half way (file size limit, SIGXFSZ ignored so that write says EFBIG)
(trap '' XFSZ; ulimit -f 4 && exec "$SCN" render scene.scn -W 200 -H 150 -o keep.ppm) >"$work/out" 2>"$work/err"
status=$?
[ "$status" -eq 3 ] || fail "a write past the file size limit exited $status, expected 3"
expect_grep "$work/err" "keep.ppm.*File too large"
same_bytes d8.png keep.ppm "a write that failed half way"
no_temp "a write that failed half way"
# a directory that cannot be written (meaningless for root, who can write anyway)
mkdir locked
cp d8.png locked/keep.png
chmod a-w locked
if ! (: >locked/probe) 2>/dev/null; then
	expect_status 3 "$SCN" render scene.scn -o locked/keep.png
	expect_grep "$work/err" 'Permission denied'
	same_bytes d8.png locked/keep.png "an unwritable directory"
	expect_status 3 "$SCN" render scene.scn -o locked/new.png
	[ -e locked/new.png ] && fail "an unwritable directory got a new file"
fi
chmod u+w locked
# --- a render that can show nothing but the sky is warned about (scn check says nothing) ---
printf 'camera { resolution 8, 6 }\nlight { position <0, 5, 0> }\n' >empty.scn
expect_status 0 "$SCN" render empty.scn -o empty.png -q
only_line "$work/err" "scn: warning: the scene has no objects: its image is the sky alone"
expect_status 0 "$SCN" check empty.scn
only_line "$work/err" ""
printf 'camera { resolution 8, 6 }\nsphere { <0, 0, 0>, 1 }\n' >dark.scn
expect_status 0 "$SCN" render dark.scn -o dark.png -q
only_line "$work/err" "scn: warning: the scene has no lights and no material emits: its objects show only the sky they reflect or transmit"
printf 'camera { resolution 8, 6 }\nsphere { <0, 0, 0>, 1  material { emit 1 } }\n' >glow.scn
expect_status 0 "$SCN" render glow.scn -o glow.png -q
only_line "$work/err" ""

# a temporary file's name holds the process's id: one left by a dead process that had
# this one's id is no one's, and does not stop the write (it failed with "File exists")
sh -c 'echo stale >.scn-$$-0.tmp; exec "$0" render scene.scn -q -o stale.png' "$SCN" ||
	fail "a stale temporary file of this process's id stopped the write"
[ -s stale.png ] || fail "no stale.png"
no_temp "a stale temporary file"
finish

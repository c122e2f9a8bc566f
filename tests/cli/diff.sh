# diff.sh: `scn diff`: the metrics of identical images and of a known difference (exact
# counts, the 1/255 boundary), --downsample, --ppm, thresholds and their exit statuses,
# size mismatch, unreadable files, usage errors, the heatmap, PNG transfer chunks, and,
# when povray is installed, POV-Ray's 16-bit linear PNG and PPM against scn's render of
# the same scene. Images are tiny so that the script takes about a second (two more
# with povray).
. "$SCN_SRCDIR/tests/lib.sh"

cd "$work" || exit 99

# ppm FILE W H MAXVAL: writes a binary PPM whose samples (decimal, row by row, r g b)
# come from standard input
ppm() {
	{
		printf 'P6\n%d %d\n%d\n' "$2" "$3" "$4"
		for v in $(cat); do
			if [ "$4" -gt 255 ]; then
				printf "\\$(printf %03o $((v >> 8)))\\$(printf %03o $((v & 255)))"
			else
				printf "\\$(printf %03o "$v")"
			fi
		done
	} >"$1"
}

# repeat N WORDS: WORDS N times
repeat() {
	n=$1
	shift
	i=0
	while [ "$i" -lt "$n" ]; do
		echo "$@"
		i=$((i + 1))
	done
}

# metric NAME: the number after NAME in the last diff's output
metric() {
	awk -v name="$1" '$1 == name { print $2 }' "$work/out"
}

# near WHAT GOT WANT TOL: |GOT - WANT| <= TOL
near() {
	awk -v g="$2" -v w="$3" -v t="$4" 'BEGIN { d = g - w; if (d < 0) d = -d; exit !(g != "" && d <= t) }' ||
		fail "$1: $2, expected $3 within $4"
}

# --- a known difference: 8x4 linear 8-bit, every sample 100 in A ---
# B: (1, 0) green 101 (off by exactly 1/255: not more than 1/255), (2, 1) red 102
# (2/255: off by more than 1/255, not 2/255), (5, 3) green 95 and blue 110 (5 and 10/255)
repeat 32 100 100 100 | ppm a.ppm 8 4 255
{
	echo 100 100 100; echo 100 101 100; repeat 6 100 100 100     # row 0
	repeat 2 100 100 100; echo 102 100 100; repeat 5 100 100 100  # row 1
	repeat 8 100 100 100                                          # row 2
	repeat 5 100 100 100; echo 100 95 110; repeat 2 100 100 100   # row 3
} | ppm b.ppm 8 4 255
expect_status 0 "$SCN" diff a.ppm b.ppm --ppm linear
expect_grep "$work/out" '^size 8x4$'
expect_grep "$work/out" '^max 0\.0392157 at \(5, 3\)$'
expect_grep "$work/out" '^off>1/255 6\.25% \(2 pixels\)$'
expect_grep "$work/out" '^off>2/255 3\.125% \(1 pixel\)$'
near "mean" "$(metric mean)" 0.000735294 1e-9                  # (1 + 2 + 5 + 10) / 255 / 96
near "bias" "$(metric bias)" -0.000326797 1e-9                 # (-1 - 2 + 5 - 10) / 255 / 96: A - B, signed
near "rmse" "$(metric rmse)" 0.00456348 1e-8                   # sqrt((1 + 4 + 25 + 100) / 96) / 255
expect_grep "$work/out" '^rmse [0-9.e-]+ \(psnr 46\.81 dB\)$'
[ "$(wc -l <"$work/out")" -eq 7 ] || fail "diff prints $(wc -l <"$work/out") lines, expected 7"
# the same files read as sRGB (the default for PPM) differ by other amounts, same places
expect_status 0 "$SCN" diff a.ppm b.ppm
expect_grep "$work/out" '^max 0\.0[0-9]+ at \(5, 3\)$'
grep -q '^max 0\.0392157 ' "$work/out" && fail "PPM read as linear without --ppm linear"
# A's encoding and B's apart: the same file read both ways differs
expect_status 0 "$SCN" diff a.ppm a.ppm --ppm srgb,linear
near "100 as sRGB against linear" "$(metric max)" 0.264 0.001  # 0.3922 - 0.1274

# --- identical images: zeros, exactly these lines ---
cat >scene.scn <<'EOF'
camera { location <0, 1, -5>  look_at <0, 0.5, 0>  fov 57.82240163683314  resolution 32, 24 }
light  { position <-5, 6, -5> }
sphere { <0, 1, 0>, 1  material { diffuse <0.8, 0.4, 0.2> } }
plane  { <0, 1, 0>, 0  material { diffuse 0.6 } }
EOF
for out in s8.png s16.png s16.ppm sf.exr; do
	case $out in
	s16.*) opts="--bit-depth 16" ;;
	*.exr) opts="--float" ;;
	*) opts="" ;;
	esac
	"$SCN" render scene.scn -q -o "$out" $opts || fail "scn render -o $out exited $?"
done
cat >zeros.expect <<'EOF'
size 32x24
rmse 0 (psnr inf dB)
mean 0
bias 0
max 0
off>1/255 0% (0 pixels)
off>2/255 0% (0 pixels)
EOF
for f in s8.png sf.exr a.ppm; do
	expect_status 0 "$SCN" diff "$f" "$f" --max-error 0 --max-rmse 0 --max-off 0
	[ "$f" = a.ppm ] && sed -i 's/^size 32x24$/size 8x4/' zeros.expect
	diff -u zeros.expect "$work/out" || fail "diff of $f with itself"
done

# --- formats, each in linear light: 8- and 16-bit sRGB PNG (sRGB chunk), 16-bit sRGB PPM
# against the 32-bit float EXR; a PPM read as linear is far off ---
expect_status 0 "$SCN" diff s16.png sf.exr --max-error 2/65535  # a 16-bit sRGB step is <= 3.7e-5
expect_status 0 "$SCN" diff sf.exr s16.ppm --max-error 2/65535
expect_status 0 "$SCN" diff s8.png sf.exr --max-error 0.005 --max-off 0
expect_grep "$work/out" '^off>1/255 0% \(0 pixels\)$'
expect_status 1 "$SCN" diff s16.ppm sf.exr --ppm linear --max-error 0.01
expect_grep "$work/err" 'is above --max-error'

# --- --downsample: B twice A's size ---
# each 2x2 block of B averages to A's pixel exactly (linear samples k/4 and k/16)
printf '%s\n' 0 1 2  3 0 1  4 4 0  1 2 3  3 4 2  4 4 4  2 0 1  0 0 3 | ppm big.ppm 4 2 4
printf '%s\n' 10 9 9  7 6 7 | ppm small.ppm 2 1 16   # red of block 0: (0 + 3 + 3 + 4) / 4 / 4
expect_status 0 "$SCN" diff small.ppm big.ppm --downsample 2 --ppm linear --max-error 0
expect_grep "$work/out" '^size 2x1 \(B 4x2 averaged over 2x2 blocks\)$'
expect_grep "$work/out" '^max 0$'
# a nearest-neighbour enlargement of a rendered image comes back exactly
expect_status 0 "$SCN" diff s8.png s8.png --downsample 1 --max-error 0
repeat 8 1 2 3 >row
{ cat row row; } | ppm flat1.ppm 8 2 255
{ repeat 16 1 2 3; repeat 16 1 2 3; repeat 16 1 2 3; repeat 16 1 2 3; } | ppm flat2.ppm 16 4 255
expect_status 0 "$SCN" diff flat1.ppm flat2.ppm --downsample 2 --max-error 0
# B not a multiple of N, or the wrong multiple: a failed comparison
expect_status 1 "$SCN" diff small.ppm big.ppm --downsample 3
expect_grep "$work/err" "^scn: cannot compare: B 'big.ppm' is 4x2, not a multiple of --downsample 3$"
expect_status 1 "$SCN" diff a.ppm big.ppm --downsample 2
expect_grep "$work/err" "^scn: cannot compare: A 'a.ppm' is 8x4 but B 'big.ppm' is 2x1 after --downsample 2$"

# --- thresholds: equal passes, above fails and is named; each metric on the known pair ---
expect_status 0 "$SCN" diff a.ppm b.ppm --ppm linear --max-error 10/255 --max-off 3.125% \
	--max-mean 0.0008 --max-rmse 0.005 --min-psnr 46
expect_status 1 "$SCN" diff a.ppm b.ppm --ppm linear --max-error 0.039
expect_grep "$work/err" '^scn: max 0\.0392157 at \(5, 3\) is above --max-error 0\.039$'
expect_grep "$work/out" '^max 0\.0392157 at \(5, 3\)$'       # the metrics are still printed
expect_status 1 "$SCN" diff a.ppm b.ppm --ppm linear --max-off 3
expect_grep "$work/err" '^scn: 3\.125% of pixels off by more than 2/255 is above --max-off 3%$'
expect_status 1 "$SCN" diff a.ppm b.ppm --ppm linear --max-mean 0.0007 --max-rmse 0.004 --min-psnr 47 -q
expect_grep "$work/err" 'mean 0\.000735294 is above --max-mean 0\.0007'
expect_grep "$work/err" 'rmse 0\.0045634[0-9] is above --max-rmse 0\.004'
expect_grep "$work/err" 'psnr 46\.81 dB is below --min-psnr 47'
[ -s "$work/out" ] && fail "-q printed metrics"
[ "$(wc -l <"$work/err")" -eq 3 ] || fail "three exceeded limits give $(wc -l <"$work/err") lines"
# without limits, any difference exits 0
expect_status 0 "$SCN" diff a.ppm b.ppm --ppm linear

# --- size mismatch ---
expect_status 1 "$SCN" diff a.ppm s8.png
expect_grep "$work/err" "^scn: cannot compare: A 'a.ppm' is 8x4 but B 's8.png' is 32x24$"
[ -s "$work/out" ] && fail "size mismatch printed metrics"

# --- unreadable files: exit 3 with the reason, nothing on standard output ---
expect_status 3 "$SCN" diff a.ppm missing.png
expect_grep "$work/err" "^scn: cannot read 'missing.png': No such file or directory$"
expect_status 3 "$SCN" diff missing.png a.ppm
expect_status 3 "$SCN" diff scene.scn a.ppm
expect_grep "$work/err" "^scn: cannot read 'scene.scn': not a PNG, OpenEXR or binary PPM \(P6\) image$"
mkdir adir
expect_status 3 "$SCN" diff a.ppm adir
expect_grep "$work/err" "Is a directory"
head -c 40 s8.png >cut.png
expect_status 3 "$SCN" diff cut.png s8.png
expect_grep "$work/err" "^scn: cannot read 'cut.png': "
expect_status 3 "$SCN" diff a.ppm b.ppm --heatmap nodir/heat.png
expect_grep "$work/err" "^scn: cannot write 'nodir/heat.png': No such file or directory$"

# --- usage errors: exit 2 before any file is read ---
for args in "" "a.ppm" "a.ppm b.ppm a.ppm" "a.ppm b.ppm --max-rmse -1" "a.ppm b.ppm --max-rmse x" \
	"a.ppm b.ppm --max-error 1/0" "a.ppm b.ppm --max-off 101%" "a.ppm b.ppm --max-rmse" \
	"a.ppm b.ppm --downsample 0" "a.ppm b.ppm --ppm gamma" "a.ppm b.ppm --ppm linear,srgb,srgb" \
	"a.ppm b.ppm --heatmap heat.txt" "a.ppm b.ppm --frobnicate" "missing.png a.ppm --bogus"; do
	expect_status 2 "$SCN" diff $args
	expect_grep "$work/err" '^usage: scn diff A B'
done
expect_status 0 "$SCN" diff --help
expect_grep "$work/out" '^Exit status: 0 compared'
expect_status 0 "$SCN" help diff

# --- heatmap: A's size; black where equal, coloured at the 3 differing pixels ---
repeat 32 0 0 0 | ppm black.ppm 8 4 255
expect_status 0 "$SCN" diff a.ppm b.ppm --ppm linear --heatmap heat.png
[ -f heat.png ] || fail "no heatmap written"
expect_status 0 "$SCN" diff heat.png black.ppm
expect_grep "$work/out" '^off>1/255 9\.375% \(3 pixels\)$'
expect_grep "$work/out" '^max 1 at \(1, 0\)$'               # 1/255: yellow, red channel 1
expect_status 0 "$SCN" diff a.ppm a.ppm --heatmap heat.exr
expect_status 0 "$SCN" diff heat.exr black.ppm --max-error 0
expect_status 0 "$SCN" diff a.ppm a.ppm --heatmap heat2.png
expect_status 0 "$SCN" diff heat2.png black.ppm --max-error 0
# a heatmap is written even when a limit fails, and replaces an existing file
expect_status 1 "$SCN" diff a.ppm b.ppm --ppm linear --heatmap heat2.png --max-error 0
expect_status 0 "$SCN" diff heat2.png heat.png --max-error 0

# --- POV-Ray's 16-bit linear PNG (gAMA 1.0) and PPM against scn's render of the same
# scene (povray-equivalence.md: diffuse sphere and plane, one point light) ---
if ! command -v povray >/dev/null 2>&1; then
	echo "povray not found: skipping the comparison with POV-Ray"
	finish
fi
cat >scene.pov <<'EOF'
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 adc_bailout 0 ambient_light rgb 0 }
camera { perspective location <0, 1, -5> look_at <0, 0.5, 0> sky <0, 1, 0>
         right x*32/24 up y angle 57.82240163683314 }
light_source { <-5, 6, -5> color rgb 1 }
sphere { <0, 1, 0>, 1
  texture { pigment { rgb <0.8, 0.4, 0.2> } finish { ambient 0 diffuse 1 specular 0 phong 0 } } }
plane { <0, 1, 0>, 0
  texture { pigment { rgb 0.6 } finish { ambient 0 diffuse 1 specular 0 phong 0 } } }
EOF
pov() {
	HOME=$work povray -D -A -GA +Iscene.pov "$@" >/dev/null 2>&1 || fail "povray $* exited $?"
}
# in parallel: each run costs about 0.6 s of start-up
pov +W32 +H24 +FN16 File_Gamma=1.0 +Opov-lin.png &
pov +W32 +H24 +FP16 File_Gamma=1.0 +Opov-lin.ppm &
pov +W32 +H24 +FN16 +Opov-srgb.png &
pov +W64 +H48 +FN16 File_Gamma=1.0 +Opov-big.png &
wait
expect_status 0 "$SCN" diff pov-lin.png sf.exr --max-error 2/65535
expect_grep "$work/out" '^off>1/255 0% \(0 pixels\)$'
expect_status 0 "$SCN" diff pov-lin.ppm pov-lin.png --ppm linear --max-error 0
expect_status 0 "$SCN" diff sf.exr pov-lin.ppm --ppm srgb,linear --max-error 2/65535
expect_status 1 "$SCN" diff pov-lin.ppm sf.exr --max-error 2/65535  # read as sRGB: wrong
expect_status 0 "$SCN" diff pov-srgb.png sf.exr --max-error 2/65535 # sRGB chunk
# scn's 2x2 grid against POV-Ray at twice the size, averaged (povray-equivalence.md section 10)
"$SCN" render scene.scn -q -s 4 -p grid -o grid.exr --float || fail "scn render -s 4 exited $?"
expect_status 0 "$SCN" diff grid.exr pov-big.png --downsample 2 --max-error 2/65535

finish

# soft_estimate.sh: the features that converge (LANGUAGE.md section 12): a jittered area
# light and focal blur, against a high-sample reference of scn itself (a 1024-sample grid:
# its pixel positions fixed, its stream dimensions stratified). Checks that
#   - the error estimate a render reports is within 15% of the error measured against the
#     reference (less the reference's own error, which it reports too);
#   - the soft shadow's measured error falls from 4 to 64 jittered samples with an exponent
#     of at least 0.62 (random points give 0.5 to 0.56 here, stratified 0.7 and more);
#   - at 16 samples, jittered samples leave well under 0.6 of random samples' error in the
#     soft shadow (0.8 for the blur): the stream's points are stratified over the pixel's
#     samples.
. "$SCN_SRCDIR/tests/lib.sh"
cd "$work" || exit 99
cat >soft.scn <<'SCENE'
camera { location <0, 3, -6>  look_at <0, 0.6, 0>  fov 50 }
light  { position <-2, 5, -1>  area { <2, 0, 0>, <0, 0, 2>, 4, 4  jitter } }
plane  { <0, 1, 0>, 0  material { diffuse 0.8 } }
sphere { <-0.6, 0.8, 0.3>, 0.8  material { diffuse <0.9, 0.5, 0.3> } }
box    { <0.6, 0, -0.8>, <1.6, 1.2, 0.2>  material { diffuse 0.7 } }
SCENE
cp "$SCN_SRCDIR/tests/cli/focal_blur.scn" blur.scn

# estimated SCENE N PATTERN OUT: renders, prints the estimated RMSE
estimated() {
	expect_status 0 "$SCN" render "$1" -W 64 -H 48 -s "$2" -p "$3" -o "$4" --float
	sed -n 's/.*estimated RMSE \([0-9.e+-]*\)$/\1/p' "$work/err"
}
# measured A REF: scn diff's RMSE
measured() {
	expect_status 0 "$SCN" diff "$1" "$2"
	sed -n 's/^rmse \([0-9.e+-]*\) .*/\1/p' "$work/out"
}

for scene in soft blur; do
	ref_err=$(estimated $scene.scn 1024 grid ref-$scene.exr)
	[ -n "$ref_err" ] || { fail "$scene: the grid reference reported no estimate (its streams are random)"; continue; }
	for case in jittered:4 jittered:16 jittered:64 random:16; do
		pattern=${case%%:*} n=${case#*:}
		est=$(estimated $scene.scn "$n" "$pattern" $scene-$pattern-$n.exr)
		raw=$(measured $scene-$pattern-$n.exr ref-$scene.exr)
		if [ -z "$est" ] || [ -z "$raw" ]; then
			fail "$scene $pattern $n: no estimate ('$est') or no measured RMSE ('$raw')"
			continue
		fi
		got=$(awk -v m="$raw" -v r="$ref_err" 'BEGIN { d = m * m - r * r; print (d > 0 ? sqrt(d) : 0) }')
		echo "$scene $pattern $n: estimated $est, measured $raw ($got less the reference's $ref_err)"
		eval "rmse_${scene}_${pattern}_$n=$got"
		awk -v e="$est" -v g="$got" 'BEGIN { exit !(e <= 1.15 * g && g <= 1.15 * e) }' ||
			fail "$scene $pattern $n: estimated RMSE $est is not within 15% of the measured $got"
	done
done
exponent=$(awk -v a="$rmse_soft_jittered_4" -v b="$rmse_soft_jittered_64" 'BEGIN { printf "%.3f", log(a / b) / log(16) }')
echo "soft shadow: RMSE ~ N^-$exponent from 4 to 64 jittered samples"
awk -v x="$exponent" 'BEGIN { exit !(x >= 0.62) }' || fail "the soft shadow converges as N^-$exponent, slower than stratified"
ratio=$(awk -v j="$rmse_soft_jittered_16" -v r="$rmse_soft_random_16" 'BEGIN { printf "%.3f", j / r }')
echo "soft shadow at 16 samples: jittered/random error $ratio"
awk -v x="$ratio" 'BEGIN { exit !(x < 0.6) }' || fail "jittered samples are not stratified in the light: $ratio of random's error"
# focal blur: the lens and the pixel are two dimensions stratified apart, so the edges the
# lens blurs converge a little faster than random (reported), and at 16 samples clearly lower
exponent=$(awk -v a="$rmse_blur_jittered_4" -v b="$rmse_blur_jittered_64" 'BEGIN { printf "%.3f", log(a / b) / log(16) }')
ratio=$(awk -v j="$rmse_blur_jittered_16" -v r="$rmse_blur_random_16" 'BEGIN { printf "%.3f", j / r }')
echo "focal blur: RMSE ~ N^-$exponent from 4 to 64 jittered samples; at 16, jittered/random error $ratio"
awk -v x="$ratio" 'BEGIN { exit !(x < 0.8) }' || fail "jittered samples are not stratified on the lens: $ratio of random's error"
finish

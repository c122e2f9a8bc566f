# statistical.sh: what POV-Ray computes with its own random numbers, a jittered area light
# and focal blur, agrees with scn in the mean: over the image, the mean signed difference
# (scn diff's bias) is within three standard errors, the standard error being the RMSE of
# the difference over sqrt(channels): per-pixel noise that averages out, where a different
# model (a light of another size, other weights, another lens) would not. Each pair is
# rendered as run-pov does; POV-Ray's focal blur takes 37 samples, a whole hexagonal grid of
# its lens pattern (16 of its 19-point grid leave the lens lopsided: a bias of its own).
. "$SCN_SRCDIR/tests/lib.sh"
if ! command -v povray >/dev/null 2>&1; then
	echo "SKIP: povray (POV-Ray 3.7) is not installed"
	exit 77
fi
cd "$work" || exit 99
cat >area.scn <<'SCENE'
camera { location <0, 3, -6>  look_at <0, 0.6, 0>  fov 50  resolution 128, 96 }
light  { position <-2, 5, -1>  area { <3, 0, 0>, <0, 0, 3>, 3, 3  jitter } }
plane  { <0, 1, 0>, 0  material { diffuse 0.8 } }
sphere { <-0.6, 0.8, 0.3>, 0.8  material { diffuse <0.9, 0.5, 0.3> } }
box    { <0.6, 0, -0.8>, <1.6, 1.2, 0.2>  material { diffuse 0.7 } }
samples { count 4  pattern grid }
SCENE
cp "$SCN_SRCDIR/tests/cli/focal_blur.scn" blur.scn
for name in area blur; do
	expect_status 0 "$SCN" pov $name.scn -o $name.pov
	cmd=$(sed -n 's|^// Render: ||p' $name.pov)
	downsample=$(sed -n 's/.*--downsample \([0-9][0-9]*\).*/\1/p' $name.pov | head -n 1)
	grep -q 'NOT pixel-exact: POV-Ray .* agree in their mean' $name.pov || fail "$name.pov does not say it agrees in mean only"
	# one thread: POV-Ray's random numbers follow the order its threads take the image's
	# blocks in, so that with two its image (and this test's outcome) changes from run to run
	(eval "$cmd +WT1") >povray.log 2>&1 || { fail "povray failed on $name.pov"; cat povray.log; continue; }
	expect_status 0 "$SCN" render $name.scn -o $name.png --bit-depth 16 -j 2
	expect_status 0 "$SCN" diff $name.png $name-pov.png ${downsample:+--downsample "$downsample"}
	cat "$work/out"
	rmse=$(sed -n 's/^rmse \([0-9.e+-]*\) .*/\1/p' "$work/out")
	bias=$(sed -n 's/^bias \([0-9.e+-]*\)$/\1/p' "$work/out")
	size=$(sed -n 's/^size \([0-9]*\)x\([0-9]*\).*/\1 \2/p' "$work/out")
	awk -v r="$rmse" -v b="$bias" -v s="$size" -v name="$name" 'BEGIN {
		split(s, wh, " "); se = r / sqrt(3 * wh[1] * wh[2])
		printf "%s: bias %.3g, standard error %.3g: %.2f of them\n", name, b, se, (b < 0 ? -b : b) / se
		exit !((b < 0 ? -b : b) <= 3 * se) }' || fail "$name: scn and POV-Ray differ in the mean beyond their noise"
done
finish

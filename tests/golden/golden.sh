# golden.sh: the renders of scenes made of scn's own noise (tests/golden/noise.scn: every
# noise pattern, turbulence and bump pattern) equal their golden images to the last 16-bit
# step, on any number of threads: the noise is evaluated in double and every build and
# thread computes the same bits (doc/noise.md). A golden image changes only with the noise
# itself; remake it with `scn render tests/golden/noise.scn -o tests/golden/noise.png
# --bit-depth 16` and say why in the commit.
. "$SCN_SRCDIR/tests/lib.sh"

for threads in 1 3; do
	expect_status 0 "$SCN" render "$SCN_SRCDIR/tests/golden/noise.scn" -o "$work/noise.png" --bit-depth 16 -q \
		-j "$threads"
	expect_status 0 "$SCN" diff "$work/noise.png" "$SCN_SRCDIR/tests/golden/noise.png" --max-error 0 -q
done
finish

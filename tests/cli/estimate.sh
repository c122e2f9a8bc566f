# estimate.sh: the error estimate a render reports against the error measured against a
# reference (a 1024-sample jittered render): within the factor 1.5 that issue 4 asks, for
# the random, jittered and poisson patterns at 4 and 16 samples and for adaptive sampling
# (replicated pixels are unbiased for every pattern; the within-pixel sample variance was
# 1.4 to 2.6 times too high for jittered and poisson, and 2.4 times too low adaptive).
# The deterministic patterns, grid and center, report no estimate.
. "$SCN_SRCDIR/tests/lib.sh"

scene="$SCN_SRCDIR/examples/whitted.scn"
expect_status 0 "$SCN" render "$scene" -W 80 -H 60 -s 1024 -p jittered -o "$work/ref.exr" --float -q
sed 's/^samples {.*/samples { count 256  pattern jittered  target_error 0.005 }/' "$scene" >"$work/adaptive.scn"
grep -q target_error "$work/adaptive.scn" || fail "could not make the adaptive scene"
for case in random:4 random:16 jittered:4 jittered:16 poisson:4 poisson:16 adaptive:256; do
	pattern=${case%%:*}
	n=${case#*:}
	if [ "$pattern" = adaptive ]; then
		expect_status 0 "$SCN" render "$work/adaptive.scn" -W 80 -H 60 -o "$work/t.exr" --float
	else
		expect_status 0 "$SCN" render "$scene" -W 80 -H 60 -s "$n" -p "$pattern" -o "$work/t.exr" --float
	fi
	est=$(sed -n 's/.*estimated RMSE \([0-9.e+-]*\)$/\1/p' "$work/err")
	expect_status 0 "$SCN" diff "$work/t.exr" "$work/ref.exr"
	got=$(sed -n 's/^rmse \([0-9.e+-]*\) .*/\1/p' "$work/out")
	if [ -z "$est" ] || [ -z "$got" ]; then
		fail "$pattern $n: no estimate ('$est') or no measured RMSE ('$got')"
		continue
	fi
	echo "$pattern $n: estimated $est, measured $got"
	awk -v e="$est" -v g="$got" 'BEGIN { exit !(e <= 1.5 * g && g <= 1.5 * e) }' ||
		fail "$pattern $n: estimated RMSE $est is not within a factor 1.5 of the measured $got"
done

for pattern in grid center; do
	n=4
	[ "$pattern" = center ] && n=1
	expect_status 0 "$SCN" render "$scene" -W 8 -H 6 -s "$n" -p "$pattern" -o "$work/t.png"
	grep -q 'estimated RMSE' "$work/err" && fail "$pattern: a deterministic pattern reported an estimate: $(cat "$work/err")"
	grep -q 'rendered in' "$work/err" || fail "$pattern: no summary line: $(cat "$work/err")"
done
finish

# estimate.sh: the error estimate a render reports against the error measured against a
# reference (a 1024-sample jittered render): within a factor 1.5 for the random pattern
# (the half-buffer estimate is unbiased for independent samples) and, as measured so far,
# within a factor 2 for jittered and poisson, whose halves are not quite independent.
. "$SCN_SRCDIR/tests/lib.sh"

scene="$SCN_SRCDIR/examples/whitted.scn"
expect_status 0 "$SCN" render "$scene" -W 80 -H 60 -s 1024 -p jittered -o "$work/ref.exr" --float -q
for case in random:4:1.5 random:16:1.5 jittered:4:2 jittered:16:2 poisson:4:2 poisson:16:2; do
	pattern=${case%%:*}
	rest=${case#*:}
	n=${rest%%:*}
	factor=${rest#*:}
	expect_status 0 "$SCN" render "$scene" -W 80 -H 60 -s "$n" -p "$pattern" -o "$work/t.exr" --float
	est=$(sed -n 's/.*estimated RMSE \([0-9.e+-]*\)$/\1/p' "$work/err")
	expect_status 0 "$SCN" diff "$work/t.exr" "$work/ref.exr"
	got=$(sed -n 's/^rmse \([0-9.e+-]*\) .*/\1/p' "$work/out")
	if [ -z "$est" ] || [ -z "$got" ]; then
		fail "$pattern $n: no estimate ('$est') or no measured RMSE ('$got')"
		continue
	fi
	echo "$pattern $n: estimated $est, measured $got (allowed factor $factor)"
	awk -v e="$est" -v g="$got" -v f="$factor" 'BEGIN { exit !(e <= f * g && g <= f * e) }' ||
		fail "$pattern $n: estimated RMSE $est is not within a factor $factor of the measured $got"
done
finish

# accel-grid.sh: every extreme scene with a property keeps it when the uniform grid
# (--accel grid) replaces the BVH: offsets, scales, rays along cell and box faces, deep
# mirrors. run-extreme checks each, as for the BVH.
. "$SCN_SRCDIR/tests/lib.sh"

cd "$SCN_SRCDIR/tests/extreme" || exit 99
n=0
for expect in *.expect; do
	name=${expect%.expect}
	n=$((n + 1))
	SCN=$SCN PROBE=$PROBE sh ./run-extreme "$name.scn" grid >"$work/log" 2>&1 ||
		fail "$name with --accel grid: $(cat "$work/log")"
done
[ "$n" -ge 25 ] || fail "only $n extreme scenes found"
finish

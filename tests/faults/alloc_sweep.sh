# alloc_sweep.sh: running out of memory at any allocation of a run goes through the one
# cleanup path. For each allocation N of a small render that reads a mesh file and a sky
# image and reports a warning (so the scanner's, the diagnostics', the lowering's and
# the render's allocations all count), SCN_ALLOC_FAIL=N fails that allocation: the run
# must end with status 4 and "scn: out of memory (...)" as its last line, leave no
# temporary file, and leave the image already at the output path untouched. Then the
# same for scn pov's output, and for a render on two threads.
. "$SCN_SRCDIR/tests/lib.sh"

cd "$work" || exit 99
cat >sweep.scn <<EOF
camera { location <0, 1, -5>  look_at <0, 0.5, 0>  resolution 8, 6 }
light { position <0, 0.5, 0> }
light { direction <1, -1, 1>  intensity 0.3 }
skybox { image "$SCN_SRCDIR/examples/sky.png" }
material red { diffuse <0.8, 0.2, 0.1>  reflect 0.2 }
plane { <0, 1, 0>, 0  material red }
for i in 0 .. 2 { sphere { <i - 1, 0.5, 0>, 0.4  material red } }
mesh { "$SCN_SRCDIR/examples/bunny.ply"  translate <0, 0, -1> }
EOF

# sweep WHAT OUT CMD...: fails allocation 1, 2, ... of CMD (which writes dest/OUT) until
# a run succeeds; prints how many allocations failed in turn
sweep() {
	what=$1 out=$2
	shift 2
	rm -rf dest && mkdir dest || exit 99
	n=1
	while [ "$n" -le 5000 ]; do
		echo old >"dest/$out"
		SCN_ALLOC_FAIL=$n "$@" >"$work/out" 2>"$work/err"
		rc=$?
		if [ "$rc" -eq 0 ]; then
			echo "$what: $((n - 1)) allocations, each failed in turn"
			[ "$n" -gt 50 ] || fail "$what: only $((n - 1)) allocations: the sweep reaches too little"
			return
		fi
		[ "$rc" -eq 4 ] || { fail "$what: allocation $n failed: status $rc, expected 4"; sed 's/^/  | /' "$work/err"; }
		tail -n 1 "$work/err" | grep -Eq '^scn: out of memory \(.+\)$' ||
			{ fail "$what: allocation $n failed: no out-of-memory message last"; sed 's/^/  | /' "$work/err"; }
		[ "$(ls -A dest)" = "$out" ] || fail "$what: allocation $n failed: left $(ls -A dest | tr '\n' ' ')"
		[ "$(cat "dest/$out")" = old ] || fail "$what: allocation $n failed: the old $out changed"
		cat "$work/err" >>"$work/messages"
		n=$((n + 1))
	done
	fail "$what: still failing after 5000 allocations"
}

: >"$work/messages"
sweep "scn render" keep.png "$SCN" render sweep.scn -o dest/keep.png -s 4 -j 1 -q
sweep "scn render -j 2" keep.png "$SCN" render sweep.scn -o dest/keep.png -W 40 -H 32 -s 4 -j 2 -q
sweep "scn pov" keep.pov "$SCN" pov sweep.scn -o dest/keep.pov
# the libraries' allocations that xcheck counts were reached too
expect_grep "$work/messages" '^scn: out of memory \(diagnostics\)$'
expect_grep "$work/messages" '^scn: out of memory \(requesting [0-9]+ bytes\)$'
finish

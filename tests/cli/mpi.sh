# mpi.sh: scn render under Open MPI's mpirun (LANGUAGE.md section 13): 1 to 4 processes
# give the bytes of one process for every pattern, adaptive sampling, a mesh, a region,
# PNG and EXR, and an animation (whole frames per process, or each frame shared); one
# set of diagnostics and one exit status; summed --stats; a killed process ends the run
# with no output and no temporary file; plain scn does not link MPI, and without scn-mpi
# refuses to run as several processes. Skipped where mpirun or scn-mpi is missing.
. "$SCN_SRCDIR/tests/lib.sh"

command -v mpirun >/dev/null || { echo "SKIP: no mpirun (apt-get install openmpi-bin)"; exit 77; }
[ -x "$(dirname "$SCN")/scn-mpi" ] || { echo "SKIP: built without MPI (no scn-mpi)"; exit 77; }
# Open MPI refuses root unless told (containers and CI run as root)
if [ "$(id -u)" = 0 ]; then
	export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
# Under AddressSanitizer, Open MPI's own allocations that it never frees (and those of
# its components, unloaded before the leak check can name them) would fail every run:
# leak checking is off for scn-mpi, whose code is scn's, leak-checked everywhere else.
leaks=
[ "${SCN_SANITIZED:-}" = yes ] && leaks="ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
# more processes than cores, and no network but this machine's
mpi() {
	np=$1
	shift
	env $leaks mpirun --oversubscribe --mca btl self,vader -np "$np" "$SCN" "$@"
}
cd "$work" || exit 99

cat >spheres.scn <<'EOF'
camera { location <0, 1.5, -6>  look_at <0, 0.5, 0>  resolution 72, 40 }
light  { position <-4, 6, -5> }
light  { position <5, 3, -2>  color <0.3, 0.3, 0.4> }
plane  { <0, 1, 0>, -1  material { diffuse checker(<0.9, 0.9, 0.9>, <0.2, 0.3, 0.6>, 1) } }
sphere { <-1.2, 0, 0>, 1  material { diffuse <0.8, 0.2, 0.2>  reflect 0.3 } }
sphere { <1.2, 0, 0.5>, 1  material { diffuse 0.1  transmit 0.9  ior 1.5 } }
EOF
sed 's/^camera.*/&\nsamples { count 64  pattern jittered  target_error 0.01 }/' spheres.scn >adaptive.scn
grep -q target_error adaptive.scn || fail "could not make the adaptive scene"
cp "$SCN_SRCDIR/tests/unit/meshes/square.obj" . || fail "cannot copy the mesh"
cat >mesh.scn <<'EOF'
camera { location <0, 0, -3>  look_at <0, 0, 0>  resolution 40, 40 }
light  { position <2, 3, -4> }
mesh   { "square.obj"  material { diffuse <0.2, 0.7, 0.3> } }
sphere { <0.4, 0.3, -0.5>, 0.3 }
EOF

# same_as_one NAME SCENE ARGS...: one process, then 1 to 4, give the same bytes
same_as_one() {
	name=$1 scene=$2
	shift 2
	ext=${name##*.}
	"$SCN" render "$scene" -q -o "one.$ext" "$@" || { fail "$name: plain render failed"; return; }
	for np in 1 2 3 4; do
		mpi "$np" render "$scene" -q -o "np$np.$ext" "$@" >"$work/out" 2>"$work/err" ||
			{ fail "$name: mpirun -np $np failed"; cat "$work/err"; continue; }
		same_bytes "one.$ext" "np$np.$ext" "$name, $np processes"
	done
}

# --- the same bytes ---
for p in center grid random jittered poisson; do
	s=4
	[ $p = center ] && s=1
	same_as_one "$p.png" spheres.scn -p $p -s $s -j 1
done
same_as_one adaptive.png adaptive.scn -j 1
same_as_one threads.png spheres.scn -s 4 -j 2
same_as_one half.exr spheres.scn -s 4
same_as_one float.exr spheres.scn -s 4 --float
same_as_one sixteen.png spheres.scn -s 4 --bit-depth 16
same_as_one mesh.png mesh.scn -s 4
same_as_one region.png spheres.scn -s 4 --region 5,3,61,37
same_as_one part.exr spheres.scn -s 4 --tile 1/3
# a tile of 16 x 16 pixels is the unit of work: an image of one tile, and of fewer tiles
# than processes
same_as_one tiny.png spheres.scn -s 4 -W 7 -H 5

# --- animations: whole frames per process (4 over 3), or each frame shared (2 over 3) ---
cat >anim.scn <<'EOF'
camera { location <0, 0, -5>  look_at <0, 0, 0>  resolution 48, 32 }
light  { position <0, 5, -5> }
sphere { <clock * 2 - 1, 0, 0>, 1  material { diffuse <frame / 10, 0.5, 0.5> } }
EOF
mkdir one one2 spread shared
(cd one && "$SCN" render ../anim.scn -q -s 4 --frames 0..4) || fail "plain animation failed"
(cd one2 && "$SCN" render ../anim.scn -q -s 4 --frames 0..2) || fail "plain animation failed"
(cd spread && mpi 3 render ../anim.scn -q -s 4 --frames 0..4) >out 2>err || { fail "4 frames on 3 processes"; cat err; }
(cd shared && mpi 3 render ../anim.scn -q -s 4 --frames 0..2) >out 2>err || { fail "2 frames on 3 processes"; cat err; }
for k in 0 1 2 3; do
	same_bytes one/anim$k.png spread/anim$k.png "frame $k of 4 on 3 processes"
done
for k in 0 1; do
	same_bytes one2/anim$k.png shared/anim$k.png "frame $k of 2 on 3 processes"
done
[ "$(ls spread | tr '\n' ' ')" = "anim0.png anim1.png anim2.png anim3.png " ] || fail "spread frames: $(ls spread)"

# each frame is reported once, by process 0, in whatever order the frames end
(cd spread && mpi 3 render ../anim.scn -s 4 --frames 0..4 -o x%d.png) >out 2>err
[ "$(grep -c '^scn: wrote x[0-3].png (frame [0-3], clock ' err)" = 4 ] || { fail "4 'wrote' lines"; cat err; }

# --- one set of messages, process 0's status ---
printf 'camera { location <0,0,-5> look_at <0,0,0> }\nsphere { <0,0,0>, 1 material { colr <1,0,0> } }\n' >bad.scn
expect_status 1 mpi 3 render bad.scn -o bad.png
[ "$(grep -c "^bad.scn:2:32: error: unknown attribute 'colr' in material" "$work/err")" = 1 ] ||
	{ fail "the scene's error once"; cat "$work/err"; }
[ -e bad.png ] && fail "a failed render wrote bad.png"
expect_status 2 mpi 3 render spheres.scn --bogus
[ "$(grep -c "^scn: unknown option '--bogus' for render" "$work/err")" = 1 ] || { fail "the usage error once"; cat "$work/err"; }
# a usage error found once the scene is read: once too
expect_status 2 mpi 3 render spheres.scn --tile 1/50 -o p.exr
[ "$(grep -c "^scn: --tile 1/50: 50 parts are more than the 40 rows of the image$" "$work/err")" = 1 ] ||
	{ fail "the late usage error once"; cat "$work/err"; }
# a process that fails where process 0 does not (here its own folder's scene names a mesh
# that is not there): process 0 prints its messages under a line naming it, and writes nothing
mkdir d0 d1
cp spheres.scn d0/s.scn
printf 'camera { location <0,0,-5> look_at <0,0,0> }\nmesh { "missing.obj" }\n' >d1/s.scn
expect_status 1 env $leaks mpirun --oversubscribe --mca btl self,vader -np 1 --wdir d0 "$SCN" render s.scn -o out.png : \
	-np 1 --wdir d1 "$SCN" render s.scn -o out.png
expect_grep "$work/err" "^scn: error: process 1 of 2 \(on .*\) failed where process 0 did not:$"
expect_grep "$work/err" "^s.scn:2:8: error: cannot read mesh file 'missing.obj': No such file or directory$"
[ -e d0/out.png ] && fail "process 1's failure left an image"
(cd d0 && no_temp "process 1's failure")
# a frame that fails: named once, the others reported
sed 's/^sphere { <clock \* 2 - 1, 0, 0>, 1/sphere { <0, 0, 0>, 2 - frame/' anim.scn >anim_bad.scn
grep -q '2 - frame' anim_bad.scn || fail "could not make the failing animation"
mkdir bad
(cd bad && mpi 2 render ../anim_bad.scn -q -s 1 --frames 0..4) >out 2>err && fail "a failing frame: status 0"
[ "$(grep -c "^\.\./anim_bad\.scn:3:.*radius must be positive, not 0$" err)" = 1 ] || { fail "frame 2's error once"; cat err; }
grep -q '^scn: error: frame 2 (clock 0.6666666666666666) failed; ' err || { fail "the failed frame named"; cat err; }

# --- --stats: the whole image's rays, summed over the processes ---
"$SCN" render spheres.scn -s 4 -o s1.png --stats 2>s1.err >/dev/null
mpi 3 render spheres.scn -s 4 -o s3.png --stats 2>s3.err >/dev/null
for what in '^rays: ' '^error estimate: '; do
	[ "$(grep "$what" s1.err)" = "$(grep "$what" s3.err)" ] || fail "--stats '$what' differs: $(grep "$what" s1.err s3.err)"
done
grep -q 'estimated RMSE' s3.err || fail "no error estimate from 3 processes"
[ "$(grep 'estimated RMSE' s1.err | sed 's/.*RMSE//')" = "$(grep 'estimated RMSE' s3.err | sed 's/.*RMSE//')" ] ||
	fail "the error estimate depends on the process count"

# --- a process killed mid-render: the run fails, nothing is written, nothing is left,
# whichever process it was (process 0's temporary file has no name: outfile.c) ---
# rank_pid R: the pid of the scn-mpi of rank R rendering ../spheres.scn, once it runs
rank_pid() {
	for _ in $(seq 100); do
		for pid in $(pgrep -f "scn-mpi render ../spheres.scn"); do
			tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$1" && { echo "$pid"; return; }
		done
		sleep 0.1
	done
}
for rank in 1 0; do
	mkdir killed$rank
	(cd killed$rank && mpi 3 render ../spheres.scn -q -s 64 -j 1 -W 640 -H 360 -o big.png >out 2>err
	 echo $? >status) &
	runner=$!
	victim=$(rank_pid $rank)
	sleep 1
	[ -n "$victim" ] && kill -KILL "$victim"
	wait "$runner"
	[ -n "$victim" ] || fail "no process $rank to kill"
	[ "$(cat killed$rank/status)" != 0 ] || fail "the run with process $rank killed exited 0"
	[ -e killed$rank/big.png ] && fail "the run with process $rank killed wrote big.png"
	(cd killed$rank && no_temp "process $rank killed")
	grep -q "process rank $rank .* exited on signal 9" killed$rank/err || { fail "mpirun did not name process $rank"; cat killed$rank/err; }
done

# --- plain scn has no MPI, and without scn-mpi refuses to be several processes ---
if command -v ldd >/dev/null; then
	ldd "$SCN" | grep -q libmpi && fail "scn links MPI's library"
fi
mkdir alone && cp "$SCN" alone/scn || fail "cannot copy scn"
expect_status 2 env OMPI_COMM_WORLD_SIZE=4 alone/scn render spheres.scn -o alone.png
expect_grep "$work/err" "^scn: error: started by an MPI launcher \(OMPI_COMM_WORLD_SIZE is set\), but "
expect_status 0 env OMPI_COMM_WORLD_SIZE=1 alone/scn render spheres.scn -q -o alone.png
finish

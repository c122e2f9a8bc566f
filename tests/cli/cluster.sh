# cluster.sh: examples/cluster's scripts do what they say, run against stand-ins for Slurm's
# sbatch and srun and for GNU parallel that do the work here: render-frame.sh's job array
# of part.sbatch and its merge, parallel.sh's parts with a retry, and mpi.sbatch's srun
# (as mpirun, when there is MPI) each give the bytes of one scn render.
. "$SCN_SRCDIR/tests/lib.sh"

cluster="$SCN_SRCDIR/examples/cluster"
cd "$work" || exit 99
mkdir bin
ln -s "$SCN" bin/scn
export PATH="$work/bin:$PATH"

# sbatch [--parsable] [--array=A-B] [--dependency=...] [--wrap CMD | SCRIPT ARGS...]: runs
# the job at once, an array's tasks one after another with SLURM_ARRAY_TASK_ID, and prints
# a job id; every other option is Slurm's business
cat >bin/sbatch <<'EOF'
#!/bin/bash
array= wrap=
while [ $# -gt 0 ]; do
	case $1 in
	--array=*) array=${1#--array=} ;;
	--wrap) wrap=$2; shift ;;
	--*) ;;
	*) break ;;
	esac
	shift
done
echo "sbatch ${array:+--array=$array }${wrap:+--wrap $wrap}$*" >>"$SBATCH_LOG"
if [ -n "$wrap" ]; then
	bash -c "$wrap" || exit 1
elif [ -n "$array" ]; then
	for k in $(seq "${array%-*}" "${array#*-}"); do
		SLURM_ARRAY_TASK_ID=$k SLURM_CPUS_PER_TASK=1 bash "$@" || exit 1
	done
fi
echo 42
EOF
# parallel [--retries N] [other options] CMD...: CMD for each line of standard input, {}
# the line; each fails once before it succeeds, so that only the retries make it work
cat >bin/parallel <<'EOF'
#!/bin/bash
retries=1
while [ $# -gt 0 ]; do
	case $1 in
	--retries) retries=$2; shift 2 ;;
	--sshloginfile|--workdir) shift 2 ;;
	*) break ;;
	esac
done
[ "$retries" -ge 2 ] || { echo "parallel: no retries" >&2; exit 1; }
while read -r x; do
	bash -c "exit 1" # the first attempt, failed
	args=()
	for a in "$@"; do args+=("${a//\{\}/$x}"); done
	"${args[@]}" || exit 1
done
EOF
chmod +x bin/sbatch bin/parallel

cat >scene.scn <<'EOF'
camera { location <0, 1.5, -6>  look_at <0, 0.5, 0>  resolution 64, 48 }
light  { position <-4, 6, -5> }
plane  { <0, 1, 0>, -1  material { diffuse checker(<0.9, 0.9, 0.9>, <0.2, 0.3, 0.6>, 1) } }
sphere { <-1.2, 0, 0>, 1  material { diffuse <0.8, 0.2, 0.2>  reflect 0.3 } }
sphere { <1.2, 0, 0.5>, 1  material { diffuse 0.1  transmit 0.9  ior 1.5 } }
EOF
"$SCN" render scene.scn -q -o whole.png || fail "plain render"

# --- Slurm: a job array of 16 parts, then the merge ---
export SBATCH_LOG="$work/sbatch.log"
bash "$cluster/render-frame.sh" scene.scn slurm.png 16 >out 2>err || { fail "render-frame.sh"; cat err; }
same_bytes whole.png slurm.png "render-frame.sh's merge"
[ "$(ls slurm-parts | wc -l)" = 16 ] || fail "render-frame.sh: $(ls slurm-parts | wc -l) parts, not 16"
grep -q '^sbatch --array=0-15 .*part.sbatch scene.scn 16 slurm-parts$' sbatch.log || { fail "the job array"; cat sbatch.log; }
grep -q '^sbatch --wrap scn merge slurm-parts/part-\*.exr -o slurm.png$' sbatch.log || { fail "the merge job"; cat sbatch.log; }
# a part submitted again replaces its file, and the merge still gives the same bytes
SLURM_ARRAY_TASK_ID=5 bash "$cluster/part.sbatch" scene.scn 16 slurm-parts || fail "part 5 again"
"$SCN" merge slurm-parts/part-*.exr -o again.png 2>err || { fail "merge after a part again"; cat err; }
same_bytes whole.png again.png "a part rendered twice"
expect_status 1 bash "$cluster/part.sbatch" scene.scn 16 x # not a task of an array
expect_grep "$work/err" "run as a task of a job array"

# --- GNU parallel, each part retried once ---
bash "$cluster/parallel.sh" scene.scn parallel.png 16 >out 2>err || { fail "parallel.sh"; cat err; }
same_bytes whole.png parallel.png "parallel.sh"

# --- MPI through srun (here mpirun), when there is MPI ---
if command -v mpirun >/dev/null && [ -x "$(dirname "$SCN")/scn-mpi" ]; then
	[ "$(id -u)" = 0 ] && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
	leaks=
	[ "${SCN_SANITIZED:-}" = yes ] && leaks="ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
	cat >bin/srun <<EOF
#!/bin/bash
while [ \$# -gt 0 ]; do case \$1 in --*) shift ;; *) break ;; esac; done
exec env $leaks mpirun --oversubscribe --mca btl self,vader -np 3 "\$@"
EOF
	chmod +x bin/srun
	SLURM_CPUS_PER_TASK=1 bash "$cluster/mpi.sbatch" scene.scn mpi.png -q >out 2>err || { fail "mpi.sbatch"; cat err; }
	same_bytes whole.png mpi.png "mpi.sbatch"
else
	echo "no MPI: mpi.sbatch not tried"
fi
finish

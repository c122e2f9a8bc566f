#!/bin/bash
# render-frame.sh SCENE OUT [PARTS]: renders one frame on a Slurm cluster as PARTS parts
# (default 64), a job array of part.sbatch, and merges them into OUT once every part is
# done. Slurm retries a part whose node fails (--requeue); a part that fails for good
# holds the merge back: submit it again (sbatch --array=K part.sbatch SCENE PARTS DIR),
# then run the merge line below by hand. scn merge names any part that is missing.
set -eu
scene=$1 out=$2 parts=${3:-64}
dir=${out%.*}-parts
here=$(cd "$(dirname "$0")" && pwd)
array=$(sbatch --parsable --array=0-$((parts - 1)) "$here/part.sbatch" "$scene" "$parts" "$dir")
sbatch --dependency=afterok:"$array" --job-name=scn-merge --output=scn-merge-%j.log \
	--wrap "scn merge $dir/part-*.exr -o $out"

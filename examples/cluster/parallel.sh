#!/bin/bash
# parallel.sh SCENE OUT [PARTS]: renders one frame as PARTS parts (default 64) with GNU
# parallel, over the machines listed in nodes.txt (one ssh login a line; ':' is this
# machine) when it is there, each part retried up to 3 times, then merges them into OUT.
# Every machine must see SCENE, its files and the parts' folder at the same path.
set -eu
scene=$1 out=$2 parts=${3:-64}
dir=${out%.*}-parts
mkdir -p "$dir"
nodes=()
[ -f nodes.txt ] && nodes=(--sshloginfile nodes.txt --workdir "$PWD")
seq 0 $((parts - 1)) | parallel --retries 3 "${nodes[@]}" \
	scn render "$scene" --tile {}/"$parts" -q -o "$dir/part-{}.exr"
scn merge "$dir"/part-*.exr -o "$out"

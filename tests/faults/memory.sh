# memory.sh: a request too big for the machine is refused before any of it is allocated,
# status 4, naming the place in the scene or the option, what it needs and what there is
# (here a ulimit -v); running out of memory anyway (SCN_ALLOC_LIMIT makes an allocation
# fail) is status 4 with a message, leaving no output or temporary file.
. "$SCN_SRCDIR/tests/lib.sh"
. "$SCN_SRCDIR/tests/hostile/lib-hostile.sh"

cd "$work" || exit 99
mkdir dest
echo old >dest/keep.png

# no_output WHAT: dest/ holds only the untouched keep.png
no_output() {
	[ "$(ls -A dest)" = keep.png ] || fail "$1 left in dest/: $(ls -A dest | tr '\n' ' ')"
	[ "$(cat dest/keep.png)" = old ] || fail "$1 changed the existing output"
}

# --- out of memory during the work: status 4, the message, nothing left behind ---
# the image (360000 bytes), allocated after the output file was created
expect_status 4 env SCN_ALLOC_LIMIT=300000 "$SCN" render "$SCN_SRCDIR/examples/whitted.scn" -W 200 -H 150 -o dest/keep.png
[ "$(cat "$work/err")" = "scn: out of memory (requesting 360000 bytes)" ] || fail "image: $(cat "$work/err")"
no_output "out of memory for the image"
# each render thread's sample buffer (40000 x 2 doubles), in the threads themselves
expect_status 4 env SCN_ALLOC_LIMIT=600000 "$SCN" render "$SCN_SRCDIR/examples/whitted.scn" -W 8 -H 6 -s 40000 -j 2 \
	-o dest/keep.png
expect_grep "$work/err" '^scn: out of memory \(requesting 640000 bytes\)$'
no_output "out of memory in a render thread"

# --- too big for the machine, refused up front ---
if [ "$vmem" = unlimited ]; then
	echo "SKIP the ulimit -v cases: a sanitizer build needs its own address space"
	finish
fi
vmem=2000000
printf 'camera { resolution 16384, 16384 }\nsphere { <0, 0, 5>, 1 }\n' >big.scn
expect_capped 4 10 "$SCN" render big.scn -o dest/keep.png
expect_grep "$work/err" '^big\.scn:1:10: error: a 16384 x 16384 image needs 3\.0 GiB; ulimit -v leaves 1\.[0-9] GiB$'
expect_grep "$work/err" '^    1 \| camera \{ resolution 16384, 16384 \}$'
no_output "an image too big (scene)"
expect_capped 4 10 "$SCN" render big.scn -W 16000 -H 16000 -o dest/keep.png
expect_grep "$work/err" '^scn: error: -W 16000 -H 16000: a 16000 x 16000 image needs 2\.9 GiB; ulimit -v leaves 1\.[0-9] GiB$'
no_output "an image too big (-W -H)"
expect_capped 4 10 "$SCN" render big.scn --region 0,0,16384,16000 -o dest/keep.png
expect_grep "$work/err" '^scn: error: --region 0,0,16384,16000: a 16384 x 16000 image needs 2\.9 GiB'
# a region that fits is allowed: the image is the region's
expect_capped 0 10 "$SCN" render big.scn --region 0,0,16,16 -o dest/region.png
rm -f dest/region.png
expect_capped 4 10 "$SCN" converge big.scn --no-pov -W 8000 -q
expect_grep "$work/err" '^scn: error: -W/-H: converging at 8000 x 8000, with 5 images at once, needs 3\.6 GiB; ulimit -v leaves'
# an image file whose header asks for more than there is
printf 'P6\n16384 16384\n255\n' >big.ppm
expect_capped 4 10 "$SCN" diff big.ppm big.ppm
expect_grep "$work/err" "^scn: cannot read 'big\.ppm': its 16384 x 16384 image needs 3\.0 GiB; ulimit -v leaves"
# the same image as a sky
printf 'skybox { image "big.ppm" }\n' >sky.scn
expect_capped 4 10 "$SCN" render sky.scn -o dest/keep.png
expect_grep "$work/err" "^sky\.scn:1:1: error: cannot read the skybox image: cannot read '.*big\.ppm': its 16384 x 16384 image needs 3\.0 GiB; ulimit -v leaves"
no_output "a sky image too big"

# 4000 copies of the bunny: 14.7 million triangles and their BVH, refused at the mesh
# where the count passes what there is, before anything is built; scn check, which builds
# nothing, reads it
printf 'camera { resolution 64, 48 }\nfor i in 0 .. 4000 { mesh { "%s"  translate <i, 0, 0> } }\n' \
	"$SCN_SRCDIR/examples/bunny.ply" >bunnies.scn
expect_capped 4 10 "$SCN" render bunnies.scn -o dest/keep.png
expect_grep "$work/err" '^bunnies\.scn:2:22: error: the render needs 6\.[0-9] GiB for 14696000 triangles, their BVH and the image; ulimit -v leaves 1\.[0-9] GiB \(this mesh passes it\)$'
no_output "4000 bunnies"
expect_capped 0 10 "$SCN" check bunnies.scn

# a mesh file whose import (assimp's post-processing, which crashes when memory runs out,
# and the copy and join after it) needs more than there is: 490000 vertices, 976206
# triangles
gen grid.ply "
import struct, sys
n = 700
w = sys.stdout.buffer
w.write(b'ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n'
        b'element face %d\nproperty list uchar int vertex_indices\nend_header\n' % (n * n, 2 * (n - 1) * (n - 1)))
w.write(b''.join(struct.pack('<fff', i / n, j / n, 0) for i in range(n) for j in range(n)))
w.write(b''.join(struct.pack('<BiiiBiii', 3, a, a + 1, a + n + 1, 3, a, a + n + 1, a + n)
                 for a in (i * n + j for i in range(n - 1) for j in range(n - 1))))
"
printf 'mesh { "grid.ply" }\n' >grid.scn
vmem=120000
expect_capped 4 20 "$SCN" render grid.scn -o dest/keep.png
expect_grep "$work/err" "^grid\.scn:1:8: error: reading mesh file 'grid\.ply' \(490000 vertices, 2931606 face corners\) needs 82\.1 MiB; ulimit -v leaves [0-9.]+ MiB$"
no_output "a mesh file too big to read"
vmem=2000000
expect_capped 0 20 "$SCN" check grid.scn
finish

# area_shared.sh: an area light's tests share one walk of the tree (the leaves its pyramid
# meets) from 25 tests up, and a point whose pyramid meets no leaf and no plane settles its
# tests without rays; each test must see exactly what its own walk would: the same image
# with the BVH (shared walks, settled tests), the uniform grid (a walk per test) and no
# accelerator (one leaf), over every kind of shape, a mesh, CSG, a transparent occluder, a
# second plane that cuts some pyramids (the wall at z = 3.5 hides the far part of the third
# light from the floor), a light the surface straddles (tests on both sides of it), and
# circular, orient and jittered lights.
. "$SCN_SRCDIR/tests/lib.sh"
cd "$work" || exit 99
cat >area.scn <<'SCENE'
camera { location <0, 4, -7>  look_at <0, 0.5, 0>  fov 55  resolution 64, 48 }
light  { position <-2, 5, -1>  area { <2, 0, 0>, <0, 0, 2>, 6, 6 } }
light  { position <3, 2, 1>  color <0.3, 0.4, 0.6>  area { <0, 3, 0>, <0, 0, 3>, 5, 5  jitter } }
light  { position <0, 6, 3>  color <0.4, 0.3, 0.2>  area { <2, 0, 0>, <0, 2, 0>, 6, 6  circular  orient } }
samples { count 4  pattern jittered }
plane  { <0, 1, 0>, 0  material { diffuse 0.8 } }
plane  { <0, 0, -1>, -3.5  material { diffuse 0.6 } }
sphere { <-1, 0.7, 0>, 0.7 }
box    { <0.3, 0, -0.9>, <1.2, 1.4, -0.2> }
cylinder { <1.8, 0, 0.8>, <1.8, 1.2, 0.8>, 0.3 }
cone   { <-2.2, 0, -1>, 0.5, <-2.2, 1.2, -1>, 0 }
torus  { 0.4, 0.12  translate <0.5, 0.12, 1.2> }
difference { box { <-0.5, 0, 1.8>, <0.5, 1, 2.6> }  sphere { <0, 1, 2.2>, 0.5 } }
sphere { <2.3, 0.5, -1.5>, 0.5  material { diffuse 0.1  transmit <0.8, 0.5, 0.3>  ior 1 } }
mesh { vertices { <-3, 0, 2>, <-2, 1.5, 2.5>, <-1.5, 0, 3> }  faces { <0, 1, 2> } }
SCENE
for accel in bvh grid none; do
	expect_status 0 "$SCN" render area.scn --accel $accel -o $accel.exr --float --stats
	grep -q 'area shadow [1-9]' "$work/err" || fail "$accel: no area shadow rays counted"
	settled=$(grep -c 'and [1-9][0-9]* tests settled' "$work/err")
	[ "$accel" = grid ] && [ "$settled" != 0 ] && fail "the grid settled tests without rays"
	[ "$accel" = bvh ] && [ "$settled" = 0 ] && fail "no test settled without a ray: $(grep rays "$work/err")"
done
expect_status 0 "$SCN" diff bvh.exr grid.exr --max-error 1e-6
expect_status 0 "$SCN" diff bvh.exr none.exr --max-error 1e-6
finish

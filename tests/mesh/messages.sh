# messages.sh: what scn says about mesh files that assimp reads but that draw nothing:
# vertices that are not finite are an error naming the file (a glTF's float inf, an
# OBJ's inf, nan and 1e39).
. "$SCN_SRCDIR/tests/lib.sh"

cd "$work" || exit 99
cp "$SCN_SRCDIR/tests/unit/meshes/infinite.gltf" "$SCN_SRCDIR/tests/unit/meshes/infinite.obj" . || exit 99

# scene MESH: a scene of that one mesh statement, as scene.scn
scene() {
	printf 'camera { location <0, 0, -4>  look_at <0, 0, 0> }\nlight { position <0, 4, -4> }\n%s\n' "$1" \
		>scene.scn
}

# expect_first STATUS LINE: scn check scene.scn exits STATUS, its first line LINE
expect_first() {
	expect_status "$1" "$SCN" check scene.scn
	[ "$(head -n 1 "$work/err")" = "$2" ] || { fail "expected '$2'"; sed 's/^/  | /' "$work/err"; }
}

scene 'mesh { "infinite.gltf" }'
expect_first 1 "scene.scn:3:8: error: mesh file 'infinite.gltf': 2 of its 3 vertices have coordinates that are not finite (inf or nan, or beyond float's 3.4e38)"
scene 'mesh { "infinite.obj" }'
expect_first 1 "scene.scn:3:8: error: mesh file 'infinite.obj': 3 of its 5 vertices have coordinates that are not finite (inf or nan, or beyond float's 3.4e38)"
# the render stops at the same error, with no image
expect_status 1 "$SCN" render scene.scn -W 8 -H 6 -q -o out.png
[ ! -e out.png ] || fail "a render with a non-finite mesh wrote out.png"
finish

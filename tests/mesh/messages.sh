# messages.sh: what scn says about mesh files that assimp reads but that draw nothing or
# only part: vertices that are not finite are an error naming the file (a glTF's float
# inf, an OBJ's inf, nan and 1e39), triangles without area a warning that says why
# (corners that coincide, as assimp makes of an OFF face line without its indices, or on
# one line), and a PLY header line that scn's checks do not know loads as assimp reads it.
# A file's texture that cannot be read is an error naming the mesh file and the texture;
# one without texture coordinates falls back to its colour with a warning; `map uv` on a
# mesh file without texture coordinates is an error.
. "$SCN_SRCDIR/tests/lib.sh"

cd "$work" || exit 99
cp "$SCN_SRCDIR/tests/unit/meshes/infinite.gltf" "$SCN_SRCDIR/tests/unit/meshes/infinite.obj" \
	"$SCN_SRCDIR/tests/unit/meshes/unknown_lines.ply" . || exit 99
# as assimp's OFF/invalid.off: a face line that gives its count but not its indices,
# which assimp reads as vertex 0 three times
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3\n' >short_face.off
# as assimp's OBJ/number_formats.obj: the face joins three points of one line
printf 'v 0 0 0\nv 1 2 3\nv -1 -2 -3\nf 1 2 3\n' >on_a_line.obj

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

scene 'mesh { "short_face.off" }'
expect_first 0 "scene.scn:3:1: warning: this mesh is not drawn: none of its 1 triangles has an area (1 has coinciding corners)"
scene 'mesh { "on_a_line.obj" }'
expect_first 0 "scene.scn:3:1: warning: this mesh is not drawn: none of its 1 triangles has an area (1 has its corners on one line)"
# some drawn, some not, for both reasons
scene 'mesh { vertices { <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <2, 0, 0> }  faces { <0, 1, 2>, <0, 1, 1>, <0, 1, 3>, <2, 2, 2> } }'
expect_first 0 "scene.scn:3:1: warning: 3 of this mesh's 4 triangles have no area and are not drawn (2 have coinciding corners, 1 has its corners on one line)"

# a header line of Blender 2.4 without "comment", obj_info, a property type that assimp
# does not know: the file loads, with nothing to say
scene 'mesh { "unknown_lines.ply" }'
expect_status 0 "$SCN" check scene.scn
only_line "$work/err" ""
expect_status 0 "$SCN" render scene.scn -W 8 -H 6 -q -o out.png

# a file's texture: missing, not an image scn reads, without texture coordinates
mkdir textures
printf 'mtllib tex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl t\nf 1/1 2/2 3/3\n' >tex.obj
printf 'newmtl t\nKd 1 0 0\nmap_Kd textures/missing.png\n' >tex.mtl
scene 'mesh { "tex.obj" }'
expect_first 1 "scene.scn:3:8: error: cannot read texture 'textures/missing.png' of mesh file 'tex.obj': cannot read 'textures/missing.png': No such file or directory"
rm -f out.png
expect_status 1 "$SCN" render scene.scn -W 8 -H 6 -q -o out.png
[ ! -e out.png ] || fail "a render with a missing texture wrote out.png"
printf 'not an image\n' >textures/missing.png
expect_first 1 "scene.scn:3:8: error: cannot read texture 'textures/missing.png' of mesh file 'tex.obj': cannot read 'textures/missing.png': not a PNG, OpenEXR or binary PPM (P6) image"
# a material of the scene's: the file's own, and its texture, are not asked for
scene 'mesh { "tex.obj"  material { diffuse 0.5 } }'
expect_status 0 "$SCN" check scene.scn
printf 'mtllib tex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl t\nf 1 2 3\n' >no_uv.obj
scene 'mesh { "no_uv.obj" }'
expect_first 0 "scene.scn:3:8: warning: mesh file 'no_uv.obj' gives texture 'textures/missing.png' but no texture coordinates: its diffuse colour is used instead"
cp "$SCN_SRCDIR/examples/sky.png" . || exit 99
scene 'mesh { "no_uv.obj"  material { diffuse image { "sky.png" map uv } } }'
expect_first 1 "scene.scn:3:1: error: 'map uv' needs texture coordinates, and mesh file 'no_uv.obj' has none"
finish

# mesh_materials.sh: scn check --dump lists the materials that objects without their own
# take from their mesh files (LANGUAGE.md section 11), once a file, after the scene.
. "$SCN_SRCDIR/tests/lib.sh"

meshes="$SCN_SRCDIR/tests/unit/meshes"
mkdir "$work/textures"
cp "$meshes/materials.obj" "$meshes/materials.mtl" "$meshes/glass.obj" "$meshes/glass.mtl" \
	"$meshes/embedded.gltf" "$meshes/square.obj" "$work/" || fail "cannot copy the meshes"
cp "$meshes/textures/checker.png" "$work/textures/" || fail "cannot copy the texture"
cat >"$work/scene.scn" <<'SCN'
material m { diffuse 0.5 }
mesh { "materials.obj" }
mesh { "materials.obj"  translate <0, 0, 1> }   // the same file: listed once
mesh { "glass.obj"  material m }                // its own material: the file's are not used
mesh { "embedded.gltf" }                        // an embedded PNG; a nameless material
mesh { "square.obj" }                           // no materials of its own
SCN
cat >"$work/expected" <<'EOF2'
mesh_material "materials.obj" 0 'red' diffuse <1, 0, 0> specular <0.5, 0.25, 0.125> exponent 64 opacity 0.75 ior 1.5 emission <0.25, 0.5, 0>
mesh_material "materials.obj" 1 'textured' diffuse <0.5, 0.5, 0.5> texture "textures/checker.png" specular <0, 0, 0> exponent 0 opacity 1 ior 1 emission <0, 0, 0>
mesh_material "embedded.gltf" 0 '' diffuse <0.5, 0.5, 0.5> texture "*0" embedded png specular <0, 0, 0> exponent 0 opacity 1 ior 1 emission <0, 0, 0>
EOF2

expect_status 0 "$SCN" check --dump "$work/scene.scn"
grep '^mesh_material ' "$work/out" >"$work/listed"
cmp -s "$work/expected" "$work/listed" || { fail "the listing differs"; diff "$work/expected" "$work/listed"; }
# the listing comes after the scene's own lines
[ "$(tail -n 3 "$work/out")" = "$(cat "$work/expected")" ] || fail "the listing is not at the end"

# without --dump, nothing
expect_status 0 "$SCN" check "$work/scene.scn"
[ -s "$work/out" ] && fail "check without --dump printed"
finish

# pov.sh: `scn pov` (LANGUAGE.md section 8, doc/povray.md): every example translates with
# the header, the command line and the document that explains them; the recipes appear
# where they should; the output name, standard output, standard input, exit statuses and
# atomic output; and, when povray is installed, POV-Ray's render of the emitted scene
# agrees with scn's to 2/65535.
. "$SCN_SRCDIR/tests/lib.sh"

cd "$work" || exit 99

# has FILE TEXT: FILE contains TEXT literally
has() {
	grep -Fq -- "$2" "$1" || { fail "$1 lacks '$2'"; sed 's/^/  | /' "$1" | head -30; }
}

# --- every example: exit 0, the header, the command line that renders it ---
for scene in "$SCN_SRCDIR"/examples/*.scn; do
	name=$(basename "$scene" .scn)
	expect_status 0 "$SCN" pov "$scene" -o "$work/$name.pov"
	[ -s "$work/err" ] && fail "scn pov $name.scn printed: $(cat "$work/err")"
	[ -s "$name.pov" ] || { fail "no $name.pov"; continue; }
	expect_grep "$name.pov" '^#version 3\.7;$'
	expect_grep "$name.pov" '^global_settings \{ assumed_gamma 1\.0 max_trace_level [0-9]+ adc_bailout 0 ambient_light rgb 0 \}$'
	expect_grep "$name.pov" "^// Render: povray -D (-A|\+A0\.0 \+AM2 \+R[0-9] -J) \+W[0-9]+ \+H[0-9]+ \+FN16 File_Gamma=1\.0 \+I$name\.pov \+O$name-pov\.png\$"
	# (a lens: the aperture, the focal point and every sample on it; doc/povray.md, Camera)
	expect_grep "$name.pov" '^camera \{ perspective location <.*> look_at <.*> sky <.*> right x\*[0-9]+/[0-9]+ up y angle [0-9.]+( aperture [0-9.]+ focal_point <.*> blur_samples [0-9]+ variance 0)? \}$'
	expect_grep "$name.pov" '^background \{ rgb <'
	# the header names the document that explains the translation, and every document it
	# names ships with scn: a file of the source tree, or where make install puts one
	expect_grep "$name.pov" "^// How each feature is translated, and where POV-Ray's image differs: /.*/povray\.md \(doc/povray\.md in scn's source\)\.\$"
	for doc in $(sed -n '/^#version/q; p' "$name.pov" | grep -o '[^ (]*\.md'); do
		case $doc in
		/*) [ -f "$SCN_SRCDIR/doc/${doc##*/}" ] || fail "$name.pov names $doc, which is no installed document of scn" ;;
		*) [ -f "$SCN_SRCDIR/$doc" ] || fail "$name.pov names $doc, which is not in scn's source" ;;
		esac
	done
	# the comments come first: nothing but comments before #version
	awk '/^#version/ { exit } !/^\/\// { bad = 1 } END { exit bad }' "$name.pov" ||
		fail "$name.pov has something before #version that is not a comment"
done
no_temp "examples"
# the sky image is named relative to the .pov's folder
mkdir sub
expect_status 0 "$SCN" pov "$SCN_SRCDIR/examples/skybox.scn" -o sub/skybox.pov
has sub/skybox.pov 'image_map { png "'
(cd sub && grep -o 'png "[^"]*"' skybox.pov | sed 's/png "\(.*\)"/\1/' | xargs test -f) ||
	fail "skybox.pov's image path does not name sky.png from its own folder"
has sub/skybox.pov 'gamma srgb map_type 1 interpolate 2'
has sub/skybox.pov 'rotate <0, 30, 0>'

# --- the recipes ---
cat >features.scn <<'EOF'
camera { location <0, 1.5, -5> look_at <0, 0.8, 0> fov 60 resolution 40, 30 }
max_depth 6
skybox { zenith <0.15, 0.35, 0.8> horizon <0.75, 0.85, 1> }
light { position <-5, 6, -5> color <1, 0.9, 0.8> }
light { direction <0.3, -1, 0.4> color 0.3 }
light { position <4, 3, -3> color <0.2, 0.2, 0.3> shadowless }
material grey_glass { diffuse 0.05 specular 0.5 shininess 100 reflect 0.1 transmit 0.8 ior 1.5 }
material rgb_glass { diffuse 0.05 specular <0.5, 0.3, 0.2> shininess 80 transmit <0.7, 0.5, 0.3> fresnel reflect 1 ior 1.6 }
material air { diffuse 0.1 transmit 0.7 }
material chk { diffuse checker(<0.9, 0.9, 0.9>, <0.8, 0.1, 0.1>, 0.25) emit <0.05, 0, 0> }
sphere { <-1.4, 0.9, 0>, 0.8 material grey_glass }
sphere { <0.3, 0.9, 0.5>, 0.8 material rgb_glass }
sphere { <1.6, 0.6, -0.8>, 0.5 material air }
sphere { <0, 0, 0>, 0.4 material chk rotate <20, 30, 0> translate <-0.3, 0.5, -1.6> }
plane { <0, 1, 0>, -0.01 material { diffuse checker(<0.7, 0.7, 0.7>, <0.2, 0.2, 0.3>, 1) } }
mesh { vertices { <1.2, 0.1, 1.5>, <2.4, 0.1, 1.8>, <1.8, 1.5, 1.6>, <2.6, 1.3, 2.4> } faces { <0, 2, 1>, <1, 2, 3> }
       normals { <-0.1, 0.05, -1>, <0.12, 0.05, -1>, <0, 0.15, -1>, <0.2, 0.1, -0.9> } smooth
       material { diffuse <0.8, 0.6, 0.2> specular 0.3 shininess 20 } }
triangle { <-2.5, 0.05, 2>, <-1, 0.05, 2.5>, <-1.8, 1.6, 2.2> material { diffuse <0.2, 0.3, 0.8> } }
EOF
expect_status 0 "$SCN" pov features.scn
has features.pov '// Render: povray -D -A +W40 +H30 +FN16 File_Gamma=1.0 +Ifeatures.pov +Ofeatures-pov.png'
has features.pov 'camera { perspective location <0, 1.5, -5> look_at <0, 0.8, 0> sky <0, 1, 0> right x*40/30 up y angle 60 }'
has features.pov 'sky_sphere { pigment { function { min(max(y, 0), 1) } color_map { [0 rgb <0.75, 0.85, 1>] [1 rgb <0.15, 0.35, 0.8>] } } }'
has features.pov 'light_source { <-5, 6, -5> color rgb <1, 0.9, 0.8> }'
expect_grep features.pov '^light_source \{ <.*> color rgb <0\.3, 0\.3, 0\.3> parallel point_at <.*> \}$'
has features.pov 'color rgb <0.2, 0.2, 0.3> shadowless }'
# single layer: grey k_s and k_t
expect_grep features.pov 'pigment \{ rgbt <0\.250*[0-9]?, 0\.250*[0-9]?, 0\.250*[0-9]?, 0\.8> \}'
has features.pov 'reflection { rgb <0.1, 0.1, 0.1> }'
has features.pov 'interior { ior 1.5 }'
# ior exactly 1 still counts a trace level
has features.pov 'interior { ior 1.0000001 }'
# RGB k_s and k_t, Fresnel: the general recipe's four layers
has features.pov 'general recipe'
has features.pov 'reflection { rgb 0, rgb <1, 1, 1> fresnel on } conserve_energy'
expect_grep features.pov 'pigment \{ rgbf <1\.4, 1\.66+7, 1\.(5|49+8), 1> \}'
# checker with emit: layers D and E; the checker follows the object's transform
has features.pov 'checker rgbt <1.8, 1.8, 1.8, 0>, rgbt <1.6, 0.2, 0.2, 0> scale 0.25'
has features.pov 'finish { ambient 0 emission 1 diffuse 0'
expect_grep features.pov '^sphere \{ <.*>, 0\.4 material \{ scn_material_[0-9]+ transform \{ matrix <.*> inverse \} \} \}$'
has features.pov 'plane { <0, 1, 0>, -0.01 material {'
has features.pov 'mesh2 {'
has features.pov 'normal_vectors { 4,'
has features.pov 'face_indices { 2,'
has features.pov 'triangle { <-2.5, 0.05, 2>, <-1, 0.05, 2.5>, <-1.8, 1.6, 2.2> material {'

# sampling: grid renders n times the size; random patterns are the nearest AA, not exact
printf 'samples { count 4 pattern grid }\n' | cat features.scn - >grid.scn
expect_status 0 "$SCN" pov grid.scn
has grid.pov '// Render: povray -D -A +W80 +H60 +FN16 File_Gamma=1.0 +Igrid.pov +Ogrid-pov.png'
has grid.pov '--downsample 2'
printf 'samples { count 16 pattern jittered }\n' | cat features.scn - >jit.scn
expect_status 0 "$SCN" pov jit.scn
has jit.pov '// Render: povray -D +A0.0 +AM2 +R3 -J +W40 +H30 +FN16 File_Gamma=1.0 +Ijit.pov +Ojit-pov.png'
has jit.pov 'NOT pixel-exact'

# a smooth triangle with normals on both sides: POV-Ray would drop a smooth_triangle
cat >mixed.scn <<'EOF'
mesh { vertices { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> } faces { <0, 1, 2> }
       normals { <0, 0, -1>, <0.2, 0.3, 1>, <0.3, 0, -1> } smooth }
EOF
expect_status 0 "$SCN" pov mixed.scn -o -
expect_grep "$work/out" '^// 1 smooth triangle\(s\) have vertex normals on both sides'
expect_grep "$work/out" '^mesh2 \{'

# a mesh file used by several objects is declared once, in its own coordinates, and each
# object places it with a matrix and its own material (a mirrored use and a checker that
# follows its object included); a use shaded otherwise (smooth) is a mesh of its own, and
# a mesh used once is written in place as before
cat >instances.scn <<EOF
camera { location <0, 1.2, -4> look_at <0, 0.5, 0> fov 50 resolution 80, 60 }
light { position <-3, 6, -4> }
light { direction <1, -0.5, 1> intensity 0.3 }
plane { <0, 1, 0>, 0 material { diffuse 0.5 } }
mesh { "$SCN_SRCDIR/examples/bunny.ply" scale 6 rotate <0, -150, 0> translate <-0.6, 0.01, 0> smooth
       material { diffuse <0.85, 0.72, 0.55> specular 0.2 shininess 40 } }
mesh { "$SCN_SRCDIR/examples/bunny.ply" scale <-5, 5, 5> rotate <0, 150, 0> translate <0.7, 0.01, 0.4> smooth
       material { diffuse checker(<0.9, 0.9, 0.9>, <0.3, 0.5, 0.8>, 0.01) } }
mesh { "$SCN_SRCDIR/tests/pov/octa.obj" scale 0.3 translate <-1.5, 0.31, -0.5> material { diffuse <0.3, 0.6, 0.9> } }
mesh { "$SCN_SRCDIR/tests/pov/octa.obj" scale <-0.2, 0.4, 0.3> rotate <0, 30, 10> translate <1.5, 0.5, -0.5> }
mesh { "$SCN_SRCDIR/tests/pov/octa.obj" smooth scale 0.25 rotate <45, 0, 0> translate <0, 1.5, 0.5> }
EOF
expect_status 0 "$SCN" pov instances.scn
[ "$(grep -c 'vertex_vectors' instances.pov)" = 3 ] ||
	fail "instances.pov writes $(grep -c 'vertex_vectors' instances.pov) meshes' vertices, not 3 (bunny, flat and smooth octahedron)"
[ "$(grep -c '^#declare scn_mesh_[0-9]* = mesh2 {$' instances.pov)" = 2 ] ||
	fail "instances.pov does not declare exactly the bunny and the flat octahedron"
expect_grep instances.pov '^#declare scn_mesh_0 = mesh2 \{$'
[ "$(grep -c '^object { scn_mesh_0 matrix <.*> material { scn_material_[0-9]* .*}$' instances.pov)" = 2 ] ||
	fail "instances.pov does not place the bunny twice"
expect_grep instances.pov '^object \{ scn_mesh_0 matrix <.*> material \{ scn_material_[0-9]+ transform \{ matrix <.*> inverse \} \} \}$'
[ "$(grep -c '^object { scn_mesh_1 matrix <' instances.pov)" = 2 ] ||
	fail "instances.pov does not place the flat octahedron twice"
[ "$(grep -c '^mesh2 {$' instances.pov)" = 1 ] || fail "instances.pov does not write the smooth octahedron in place"
# the bunny's first vertex in the file's own coordinates (bunny.ply's, not moved)
expect_grep instances.pov '^    <0\.0203421097,0\.00191596872,0\.0398447029>, '

# --- the solids of section 9: each leaf in its canonical form under the matrix of its
# placement, inverse where inverted, CSG as union, intersection or merge ---
cat >solids.scn <<'EOF'
camera { location <0, 2, -8> look_at <0, 0.5, 0> fov 60 resolution 40, 30 }
light { position <-3, 6, -5> }
material glass { diffuse 0 transmit 0.9 ior 1.5 }
material water { diffuse 0 transmit 0.9 ior 1.33 }
material chk { diffuse checker(<1, 1, 1>, <0, 0, 0>, 0.3) }
box { <1, 2, 3>, <-1, 0.5, 0> }
box { <0, 0, 0>, <1, 1, 1> rotate <0, 90, 0> translate <2, 0, 0> }
cylinder { <0, 0, 0>, <2, 0, 0>, 0.25 open }
cone { <0, 0, 0>, 1, <0, 1, 0>, 0 }
cone { <0, 0, 0>, 0.5, <0, 0, 2>, 1 open translate <0, 1, 0> }
disc { <0, 0, 0>, <0, 1, 0>, 2, 1 }
disc { <0, 1, 0>, <0, 0, -2>, 0.5 material glass }
torus { 2, 0.5 translate <0, 1, 0> }
sphere { <0, 0, 0>, 1 scale <2, 1, 1> }
difference { box { <-1, -1, -1>, <1, 1, 1> } sphere { <0, 0, 0>, 1.2 } material glass translate <0, 0, 5> }
merge { sphere { <0, 0, 0>, 1 } sphere { <1, 0, 0>, 1 } material water translate <-3.5, 1, 5> }
intersection { sphere { <0, 0, 0>, 1 material glass } sphere { <0.5, 0, 0>, 1 material water } translate <3.5, 1, 5> }
intersection { sphere { <0, 0, 0>, 2 } union { box { <-1, 0, -1>, <1, 1, 1> } cylinder { <0, 0, 0>, <0, 2, 0>, 0.3 } inverse } translate <0, 0, 9> }
intersection { sphere { <0, 0, 0>, 1 } plane { <0, 1, 0>, 0.2 } material chk rotate <0, 0, 90> translate <6, 1, 0> }
difference { sphere { <0, 0, 0>, 1 } mesh { vertices { <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <0, 0, 1> } faces { <0, 2, 1>, <0, 1, 3>, <0, 3, 2>, <1, 2, 3> } inside_vector <0, 0, 1> } translate <-6, 1, 0> }
EOF
expect_status 0 "$SCN" pov solids.scn
[ -s "$work/err" ] && fail "scn pov solids.scn printed: $(cat "$work/err")"
# corners in any order come out low then high; an unmoved leaf has no matrix
expect_grep solids.pov '^box \{ <-1, 0\.5, 0>, <1, 2, 3> material \{ scn_material_[0-9]+ \} \}$'
# the object's transform is the matrix: the columns of the map, the translation last
has solids.pov 'box { <0, 0, 0>, <1, 1, 1> matrix <0, 0, -1, 0, 1, 0, 1, 0, 0, 2, 0, 0> material {'
# a cylinder and a cone from the origin to <0, 1, 0>, the larger radius 1, their frames in
# the matrix
expect_grep solids.pov '^cylinder \{ <0, 0, 0>, <0, 1, 0>, 1 open matrix <[^>]*> material \{'
expect_grep solids.pov '^cone \{ <0, 0, 0>, 1, <0, 1, 0>, 0 matrix <[^>]*> material \{'
expect_grep solids.pov '^cone \{ <0, 0, 0>, 0\.5, <0, 1, 0>, 1 open matrix <[^>]*> material \{'
# a disc at the origin facing y, of radius 1; its hole relative to that
expect_grep solids.pov '^disc \{ <0, 0, 0>, <0, 1, 0>, 1, 0\.5 matrix <[^>]*> material \{'
expect_grep solids.pov '^disc \{ <0, 0, 0>, <0, 1, 0>, 1 matrix <[^>]*> material \{'
has solids.pov 'torus { 2, 0.5 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0> material {'
# an ellipsoid is the unit sphere under its scale
has solids.pov 'sphere { <0, 0, 0>, 1 matrix <2, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> material {'
# a difference is an intersection with the cutters inverse; its glass members share the
# CSG's one interior, taking their material without their own
sed -n '/^intersection {$/,/^}$/p' solids.pov >csg.txt
expect_grep csg.txt '^  box \{ <-1, -1, -1>, <1, 1, 1> matrix <[^>]*> material \{ scn_material_[0-9]+_shared \} \}$'
expect_grep csg.txt '^  sphere \{ <0, 0, 0>, 1 matrix <1\.2, 0, 0, 0, 1\.2, 0, 0, 0, 1\.2, 0, 0, 5> inverse material \{ scn_material_[0-9]+_shared \} \}$'
expect_grep csg.txt '^  interior \{ ior 1\.5 \}'
expect_grep solids.pov '^#declare scn_material_[0-9]+_shared = material \{'
# merge stays merge, with its one interior
sed -n '/^merge {$/,/^}$/p' solids.pov >merge.txt
[ "$(grep -c 'material { scn_material_[0-9]*_shared }' merge.txt)" = 2 ] || fail "the merge's members do not share its interior"
has merge.txt 'interior { ior 1.33 }'
# members of different iors keep their own interiors, and the header says why
expect_grep solids.pov '^  sphere \{ <0, 0, 0>, 1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 3\.5, 1, 5> material \{ scn_material_[0-9]+ \} \}$'
expect_grep solids.pov '^// 1 transmitting solid\(s\) have members of different iors'
# an inverse union is the intersection of its members inverse (POV-Ray's De Morgan)
expect_grep solids.pov '^  intersection \{$'
expect_grep solids.pov '^    cylinder \{ <0, 0, 0>, <0, 1, 0>, 1 matrix <[^>]*, 0, 0, 9> inverse material \{'
# a plane in a CSG, in world space; a checker inherited from the CSG in the CSG's space
expect_grep solids.pov '^  plane \{ <[^>]*>, [-0-9.e]+ material \{ scn_material_[0-9]+ transform \{ matrix <[^>]*> inverse \} \} \}$'
# a closed mesh in a CSG: a mesh2 with its inside_vector, inverse as a cutter
has solids.pov '  inside_vector <0, 0, 1> inverse material {'
# a refracting disc has no inside: noted
expect_grep solids.pov '^// 1 refracting disc\(s\) and open cylinder\(s\) or cone\(s\) have no inside'

# --- names, standard input and output, statuses, atomic output ---
mkdir names && cd names || exit 99
expect_status 0 "$SCN" pov ../features.scn
[ -f features.pov ] || fail "the default output is not features.pov in the current directory"
expect_status 0 "$SCN" pov - <../features.scn
[ -f stdin.pov ] || fail "a scene from standard input does not default to stdin.pov"
has stdin.pov '+Istdin.pov +Ostdin-pov.png'
expect_status 0 "$SCN" pov ../features.scn -o -
expect_grep "$work/out" '^#version 3\.7;$'
[ -f ./- ] && fail "-o - wrote a file named -"
cd .. || exit 99

cp features.pov keep.pov
printf 'sphere { <0,0,0>, -1 }\n' >bad.scn
expect_status 1 "$SCN" pov bad.scn -o keep.pov
expect_grep "$work/err" "error: a sphere's radius must be positive"
cmp -s features.pov keep.pov || fail "a scene with errors changed the existing output"
[ -f bad.pov ] && fail "a scene with errors wrote bad.pov"
expect_status 1 "$SCN" pov bad.scn
[ -f bad.pov ] && fail "a scene with errors wrote bad.pov"
expect_status 2 "$SCN" pov
expect_grep "$work/err" 'no scene given'
expect_status 2 "$SCN" pov features.scn --bogus
expect_grep "$work/err" "unknown option '--bogus'"
expect_status 2 "$SCN" pov features.scn -o
expect_status 2 "$SCN" pov features.scn grid.scn
expect_status 3 "$SCN" pov "$work/missing.scn"
expect_status 3 "$SCN" pov features.scn -o "$work/no/such/dir/x.pov"
expect_grep "$work/err" "cannot write '.*/no/such/dir/x.pov'"
expect_status 0 "$SCN" help pov
expect_grep "$work/out" '^usage: scn pov SCENE'
no_temp "statuses"

# --- POV-Ray itself, when installed: the emitted command renders what scn renders ---
if ! command -v povray >/dev/null 2>&1; then
	echo "povray not found: skipping the renders"
	finish
fi
# povray_run POV [OPTIONS]: runs the command line of POV's // Render: comment in POV's
# folder, with OPTIONS after it (a smaller size, say)
povray_run() {
	pov=$1
	shift
	cmd="$(sed -n 's#^// Render: ##p' "$pov") $*"
	[ "$cmd" != " $*" ] || { fail "$pov has no // Render: line"; return 1; }
	(cd "$(dirname "$pov")" && HOME=$work sh -c "$cmd -GA +WT2" >/dev/null 2>&1) || { fail "'$cmd' exited $?"; return 1; }
}
# the features scene, raised off the floor everywhere (touching surfaces differ by design),
# its smooth mesh's normals tilted little: scn starts shadow rays on the curved surface they
# describe, POV-Ray on the flat one, which moves the edge of a shadow across the mesh;
# both images clip at 1 (its highlights are brighter), and scn's 16-bit sRGB PNG is within
# 1.2/65535 of the linear value, POV-Ray's linear PNG within 0.5/65535
if povray_run features.pov; then
	"$SCN" render features.scn -o features-scn.png --bit-depth 16 -q ||
		fail "scn render features.scn exited $?"
	"$SCN" diff features-scn.png features-pov.png --max-error 2/65535 >diff.out 2>&1 ||
		{ fail "POV-Ray's render of features.pov differs from scn's"; cat diff.out; }
fi
# grid sampling: POV-Ray at twice the size, averaged in 2 x 2 blocks; with dimmer lights, as
# POV-Ray clips each of its pixels at 1 before they are averaged, scn only the mean; the
# mesh flat, as at twice the size a shadow's edge crosses it where the lifted start of
# scn's shadow rays (see above) moves it
sed 's/color <1, 0.9, 0.8>/color <0.6, 0.5, 0.4>/; s/ smooth$//' grid.scn >grid2.scn
expect_status 0 "$SCN" pov grid2.scn
if povray_run grid2.pov; then
	"$SCN" render grid2.scn -o grid2-scn.exr --float -q || fail "scn render grid2.scn exited $?"
	"$SCN" diff grid2-scn.exr grid2-pov.png --downsample 2 --max-error 2/65535 >diff.out 2>&1 ||
		{ fail "POV-Ray's render of grid2.pov differs from scn's"; cat diff.out; }
fi
# the placed meshes
if povray_run instances.pov; then
	"$SCN" render instances.scn -o instances-scn.png --bit-depth 16 -q || fail "scn render instances.scn exited $?"
	# a few pixels where a shadow's edge crosses a smooth bunny: scn starts shadow rays on the
	# curved surface the normals describe, POV-Ray on the flat one (doc/povray.md); a wrong
	# placement would move whole meshes
	"$SCN" diff instances-scn.png instances-pov.png --max-off 0.1% --max-mean 0.1/255 >diff.out 2>&1 ||
		{ fail "POV-Ray's render of instances.pov differs from scn's"; cat diff.out; }
fi
# a sky image, named from the .pov's own folder
if povray_run sub/skybox.pov +W64 +H40; then
	[ -f sub/skybox-pov.png ] || fail "POV-Ray did not write sub/skybox-pov.png"
fi
finish

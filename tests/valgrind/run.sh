# run.sh: `make check-valgrind`: a representative subset of scn's work under valgrind's
# memcheck: front-end errors, the parse of every kind of statement, a small render of
# every example (each feature, PNG sky, PLY mesh), OBJ and inline meshes, a model of each
# mesh format that the man page lists (from assimp-testmodels, where installed), the three
# image formats written and read back, --tile parts and scn merge, scn pov, scn diff and a
# short scn converge. Each run must end with its usual status, no memcheck error and no
# byte definitely lost.
# Prints one line a run and a summary; exit status 0 when every run passed, 77 when
# valgrind is missing or scn is a sanitizer build, 1 otherwise.
set -u
: "${SCN:?run through make check-valgrind}"
: "${SCN_SRCDIR:?run through make check-valgrind}"
command -v valgrind >/dev/null 2>&1 || { echo "SKIP: valgrind is not installed"; exit 77; }
if nm "$SCN" 2>/dev/null | grep -q '__asan_init\|__ubsan_handle'; then
	echo "SKIP: $SCN is a sanitizer build; valgrind needs a plain one"
	exit 77
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/scn-vg.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 99
src=$SCN_SRCDIR
runs=0 fails=0
start=$(date +%s)

# vg WANT CMD...: runs scn CMD under memcheck; WANT is scn's expected exit status
vg() {
	want=$1
	shift
	runs=$((runs + 1))
	valgrind -q --error-exitcode=99 --leak-check=full --show-leak-kinds=definite \
		--errors-for-leak-kinds=definite --log-file="$work/vg.log" "$SCN" "$@" >"$work/out" 2>"$work/err"
	got=$?
	if [ "$got" -ne "$want" ] || [ -s "$work/vg.log" ]; then
		fails=$((fails + 1))
		echo "FAIL: scn $* exited $got (expected $want)"
		sed 's/^/  | /' "$work/vg.log" "$work/err" | head -60
	else
		echo "ok: scn $*"
	fi
}

# front end: errors of each phase, and the parse of every construct
for t in arg_types attribute_name caret_tab_crlf expr_nesting for_errors include_cycle include_missing \
	lex_control_byte lex_malformed_number; do
	vg 1 check "$src/tests/errors/$t.scn"
done
for t in camera for functions include_basic inline_material let lexing lights; do
	vg 0 check --dump "$src/tests/parse/$t.scn"
done

# a small render of every example: every feature, the PNG sky, the PLY bunny
for e in "$src"/examples/*.scn; do
	vg 0 render "$e" -W 32 -H 24 -s 4 -j 2 -q -o "$(basename "$e" .scn).png"
done
# OBJ meshes, an inline mesh, smooth shading
cat >meshes.scn <<SCENE
camera { location <0, 0.5, -3>  look_at <0, 0.5, 0>  resolution 24, 18 }
light  { position <-2, 4, -4> }
mesh { "$src/tests/unit/meshes/normals.obj"  smooth }
mesh { "$src/tests/unit/meshes/quad.obj"  translate <1, 0, 0> }
mesh { vertices { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }  faces { <0, 1, 2> }  translate <-1, 0, 0> }
SCENE
vg 0 render meshes.scn -q -o meshes.ppm
# a mesh file's own materials, its PNG texture looked up by its UVs
printf 'camera { location <0, 1, -6>  look_at <0, 0, 0>  resolution 16, 12 }\n%s\nmesh { "%s" }\n' \
	'light { position <-4, 8, -6> }' "$src/tests/unit/meshes/textured.gltf" >textured.scn
vg 0 render textured.scn -q -o textured.ppm
# a model of each mesh format that man/scn.1 lists, where assimp-testmodels is installed:
# memcheck sees into assimp, which the sanitizer build does not instrument
models=/usr/share/assimp/models
if [ -d "$models" ]; then
	# (a for loop, not a pipe, so that vg counts in this shell; the names have no blanks)
	# (a material of the scene's: some of them name textures in formats scn does not read)
	for m in $(grep -v '^#' "$src/tests/mesh/formats.txt"); do
		printf 'camera { location <0, 1, -6>  look_at <0, 0, 0>  resolution 16, 12 }\n%s\nmesh { "%s"  %s }\n' \
			'light { position <-4, 8, -6> }' "$models/$m" 'material { diffuse 0.8 }' >model.scn
		vg 0 render model.scn -q -o model.ppm
	done
else
	echo "skipped: the models of each mesh format (no $models: assimp-testmodels is not installed)"
fi
# every output format, every sample pattern, read back by scn diff
vg 0 render "$src/examples/whitted.scn" -W 32 -H 24 -s 9 -p grid -q -o w.exr
vg 0 render "$src/examples/whitted.scn" -W 32 -H 24 -s 9 -p grid -q --float -o w32.exr
vg 0 render "$src/examples/whitted.scn" -W 32 -H 24 -s 9 -p grid -q --bit-depth 16 -o w16.ppm
vg 0 render "$src/examples/whitted.scn" -W 32 -H 24 -s 5 -p poisson -q -o wp.png
vg 0 render "$src/examples/whitted.scn" -W 32 -H 24 -s 4 -p random --stats -q --region 4,4,20,20 -o wr.png
vg 0 diff w.exr w16.ppm --heatmap heat.png
vg 0 diff w32.exr w.exr --heatmap heat.exr
vg 0 diff wp.png whitted.png --heatmap heat.ppm
vg 1 diff w.exr w16.ppm --max-error 0
# parts of --tile (with a mesh and an image map, which the part's hash reads) and scn merge,
# and merge's refusal of a part given twice
vg 0 render "$src/examples/crate-texture.scn" -W 32 -H 24 -s 4 -q --tile 0/2 -o part0.exr
vg 0 render "$src/examples/crate-texture.scn" -W 32 -H 24 -s 4 -q --tile 1/2 -o part1.exr
vg 0 merge part1.exr part0.exr -o merged.png
vg 3 merge part0.exr part0.exr -o twice.png
# the POV-Ray twin, and the error against time without POV-Ray
vg 0 pov "$src/examples/materials.scn" -o materials.pov
vg 0 converge "$src/examples/whitted.scn" -W 12 -H 9 --reference-samples 16 --budget 5 --no-pov -q
# failures that free what they hold: a missing file, a malformed mesh, an unwritable output
vg 3 render missing.scn
printf 'mesh { "%s" }\n' "$src/tests/unit/meshes/bad_index.obj" >badmesh.scn
vg 1 render badmesh.scn -q -o bad.png
vg 3 render "$src/examples/whitted.scn" -o nodir/x.png

echo "valgrind subset: $runs runs, $fails failed, $(($(date +%s) - start)) s"
[ "$fails" -eq 0 ]

# testmodels.sh: every model file of Debian's assimp-testmodels (assimp's own test files,
# many of them broken on purpose) as a mesh, through `scn check` and, when it checks
# clean, a tiny render: each run ends within its time cap with status 0, or with 1 and an
# error that names the file; none is killed by a signal, and nothing prints a NaN. The
# files of formats.txt, one of each format that man/scn.1 lists, must load (PLY/Wuson.ply
# has a header line that scn's checks refused once; those whose textures scn cannot read
# with a material of the scene's), and the glTF box with infinite coordinates is refused as
# such.
# Skipped (77) without the package. Every file, in every build (the sanitizer build too).
. "$SCN_SRCDIR/tests/lib.sh"

models=/usr/share/assimp/models
if [ ! -d "$models" ]; then
	echo "SKIP: no $models: install assimp-testmodels (apt-get install assimp-testmodels)"
	exit 77
fi
command -v timeout >/dev/null 2>&1 || { echo "SKIP: no timeout(1)"; exit 77; }

# a file of each format that man/scn.1 lists (PLY/Wuson.ply the one with a Blender line)
must_load=$(grep -v '^#' "$SCN_SRCDIR/tests/mesh/formats.txt")
infinite=glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb
# The extensions assimp 5.2 reads (aiIsExtensionSupported) of the files the package has;
# the rest are textures, materials, buffers and notes.
exts='3d|3ds|3mf|ac|acc|amf|ase|b3d|blend|bvh|cob|csm|dae|dxf|fbx|glb|gltf|hmp|ifc|iqm|irr'
exts="$exts|irrmesh|lwo|lws|lxo|md2|md5mesh|mdc|mdl|ms3d|nff|obj|off|ogex|ply|q3o|q3s|raw|sib"
exts="$exts|smd|stl|ter|uc|x|x3d|xgl|xml|zae|zgl"
find "$models" -type f | LC_ALL=C sort | grep -Ei "\.($exts)\$" >"$work/models"
total=$(wc -l <"$work/models")
for f in $must_load $infinite; do
	[ -f "$models/$f" ] || fail "no $models/$f"
done
[ "$total" -gt 0 ] || { fail "no model files under $models"; finish; }

cd "$work" || exit 99
loaded=0 refused=0
# run NAME CMD...: runs scn CMD with a time cap; output in $work/out; sets $status
run() {
	what=$1
	shift
	timeout -k 5 60 "$SCN" "$@" >out 2>&1
	status=$?
	# a NaN printed as a number, leaving out the file's name and the message that
	# says a file's coordinates are not finite
	if sed -e "s|$file||g" -e 's/not finite (inf or nan,//' out | grep -Eiq '(^|[^a-z])nan([^a-z]|$)'; then
		fail "scn $what of $file prints a NaN"
		sed 's/^/  | /' out | head -5
	fi
}
while IFS= read -r file; do
	# the path in a string: a file name with a quote or a backslash cannot be written
	case $file in *'"'* | *'\'*) continue ;; esac
	cat >scene.scn <<EOF
camera { location <0, 1, -6>  look_at <0, 0, 0> }
light  { position <-4, 8, -6> }
mesh   { "$file" }
EOF
	run check check scene.scn
	rel=${file#"$models"/}
	case " $(echo $must_load) " in
	*" $rel "*)
		# a texture scn cannot read (TGA, JPG) is an error naming the mesh file and the
		# texture; with a material of the scene's, the file is not asked for its own
		if [ "$status" -eq 1 ] && grep -q "error: cannot read texture '.*' of mesh file '$file'" out; then
			sed '/^mesh/s/}$/  material { diffuse 0.8 } }/' scene.scn >own.scn && mv own.scn scene.scn
			run check check scene.scn
		fi
		[ "$status" -eq 0 ] || fail "$file does not load" ;;
	esac
	if [ "$rel" = "$infinite" ]; then
		grep -q "vertices have coordinates that are not finite" out || fail "$file is not refused as not finite"
	fi
	case $status in
	0)
		loaded=$((loaded + 1))
		run render render scene.scn -W 16 -H 12 -s 1 -j 1 -q --stats -o image.png
		if [ "$status" -ne 0 ]; then
			fail "scn render of $file exited $status after a clean check"
			sed 's/^/  | /' out | head -5
		elif ! grep -q '^non-finite radiance values: 0$' out; then
			fail "the render of $file has non-finite radiance values"
			grep 'non-finite' out
		fi
		;;
	1)
		refused=$((refused + 1))
		grep -F ": error: " out | grep -Fq "'$file'" || {
			fail "scn check refuses $file without an error that names it"
			sed 's/^/  | /' out | head -5
		}
		;;
	124 | 137) fail "scn check of $file did not end within 60 s" ;;
	*)
		fail "scn check of $file exited $status"
		sed 's/^/  | /' out | head -5
		;;
	esac
done <"$work/models"
echo "$total model files: $loaded loaded and rendered, $refused refused with an error naming them"
finish

# pairs.sh: each tests/pairs/NAME.scn writes a scene with the forms of LANGUAGE.md section
# 10 (macros, functions, if/else, ?:, booleans, arrays, strings), and NAME.flat.scn writes
# the same scene without them (plain objects, `let`, `for` over ranges). For each pair:
#   - both check clean (exit 0, nothing on stderr: no warning either);
#   - the twin is flat: outside comments and strings it uses none of the section's forms,
#     and NAME.scn uses at least one of them;
#   - both render (48 x 36, one sample a pixel, 32-bit EXR) to the same bytes;
#   - the render is not empty: the pairs have no sky, and at least 20 of its pixels are
#     not black, so that two scenes that both drew nothing do not pass.
# Every NAME.flat.scn in the folder is a pair; tests/pairs/local.mk lists them for the
# tarball.
. "$SCN_SRCDIR/tests/lib.sh"
dir=$SCN_SRCDIR/tests/pairs

# forms FILE: the lines of FILE, comments and strings removed, that use section 10's forms
forms() {
	sed -e 's|//.*||' -e 's|/\*.*\*/||g' -e 's|"[^"]*"|""|g' "$1" |
		grep -nE '(^|[^A-Za-z0-9_])(def|if|else|and|or|not|true|false|len|str|clock|frame)([^A-Za-z0-9_]|$)|[][?]|==|!=|<=|>='
}

printf 'count 0 0 48 36 0 0 0 0 < 1709\n' >"$work/nonempty.expect"
: >"$work/empty.stats"
pairs=0
for flat in "$dir"/*.flat.scn; do
	name=$(basename "$flat" .flat.scn)
	scene=$dir/$name.scn
	[ -f "$scene" ] || { fail "$name.flat.scn has no $name.scn"; continue; }
	pairs=$((pairs + 1))
	ok=1
	for f in "$scene" "$flat"; do
		"$SCN" check "$f" >"$work/out" 2>"$work/err"
		status=$?
		if [ "$status" -ne 0 ] || [ -s "$work/err" ]; then
			fail "$(basename "$f"): scn check exited $status"
			sed 's/^/  | /' "$work/err" | head -20
			ok=0
		fi
	done
	if forms "$flat" >"$work/forms"; then
		fail "$name.flat.scn is not flat: it uses section 10's forms"
		sed 's/^/  | /' "$work/forms"
	fi
	forms "$scene" >/dev/null || fail "$name.scn uses none of section 10's forms"
	[ "$ok" -eq 1 ] || continue
	for f in "$scene" "$flat"; do
		out=$work/$(basename "$f" .scn).exr
		(cd "$dir" && "$SCN" render "$(basename "$f")" -o "$out" -W 48 -H 36 -s 1 --float -j 2 -q \
			--no-progress) 2>"$work/err" ||
			{ fail "$(basename "$f"): scn render failed"; sed 's/^/  | /' "$work/err" | head -20; ok=0; }
	done
	[ "$ok" -eq 1 ] || continue
	cmp -s "$work/$name.exr" "$work/$name.flat.exr" ||
		fail "$name.scn and $name.flat.scn render different images"
	"${PROBE:?run through make check}" "$work/$name.flat.exr" "$work/empty.stats" "$work/nonempty.expect" \
		>"$work/probe" || { fail "$name.flat.scn renders fewer than 20 pixels that are not black"; cat "$work/probe"; }
done
[ "$pairs" -ge 8 ] || fail "only $pairs pairs in $dir"
echo "$pairs pairs"
finish

# install.sh: `make install DESTDIR=...` puts each file of editors/ where its program looks,
# unchanged: the bash completion in configure's bash-completion folder, Vim's files in the
# syntax/ and ftdetect/ folders of its vimfiles folder, the TextMate grammar in textmate/ of
# the package's data folder (SCN_INSTALL_DIRS: those three folders).
. "$SCN_SRCDIR/tests/lib.sh"
: "${SCN_BUILDDIR:?run these tests through make check}"
: "${SCN_INSTALL_DIRS:?run these tests through make check}"

root=$work/root
# a make of its own, not a part of the make that runs the tests
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -s -C "$SCN_BUILDDIR" install DESTDIR="$root" \
	>"$work/out" 2>&1 || { fail "make install DESTDIR=$root failed"; cat "$work/out"; }
# shellcheck disable=SC2086 # three folders; configure's folders hold no spaces
set -- $SCN_INSTALL_DIRS
for place in "$1/scn editors/bash/scn" "$2/syntax/scn.vim editors/vim/syntax/scn.vim" \
	"$2/ftdetect/scn.vim editors/vim/ftdetect/scn.vim" \
	"$3/textmate/scn.tmLanguage.json editors/textmate/scn.tmLanguage.json"; do
	installed=$root${place% *}
	file=${place#* }
	if [ ! -f "$installed" ]; then
		fail "make install put no $file in $installed; it put: $(cd "$root" && find . -type f | sort | tr '\n' ' ')"
	elif ! cmp -s "$SCN_SRCDIR/$file" "$installed"; then
		fail "$installed is not $file"
	fi
done
finish

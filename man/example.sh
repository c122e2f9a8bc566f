# example.sh: the example scene in scn.1 is examples/manpage.scn, word for word (the
# examples test checks that file), and the page renders without groff warnings.
. "$SCN_SRCDIR/tests/lib.sh"

page=$SCN_SRCDIR/man/scn.1
# The lines between the BEGIN and END comments, without .EX/.EE and roff escapes.
sed -n '/^\.\\" BEGIN examples\/manpage\.scn$/,/^\.\\" END examples\/manpage\.scn$/p' "$page" |
	sed -e '1d' -e '$d' -e '/^\.EX$/d' -e '/^\.EE$/d' \
	    -e 's/^\\&//' -e 's/\\-/-/g' -e 's/\\e/\\/g' >"$work/example.scn"
[ -s "$work/example.scn" ] || fail "no example between the BEGIN and END comments of scn.1"
diff -u "$SCN_SRCDIR/examples/manpage.scn" "$work/example.scn" ||
	fail "the example in man/scn.1 differs from examples/manpage.scn"

if command -v groff >/dev/null 2>&1; then
	groff -man -Tutf8 -ww -z "$page" >"$work/groff" 2>&1 || fail "groff failed on scn.1"
	[ -s "$work/groff" ] && fail "groff warns about scn.1: $(cat "$work/groff")"
fi
finish

# output.sh: an output that cannot be written is status 3 with the OS reason, for every
# command that writes files, and it is found before the work: with a scene that has
# errors (or an image that is missing) the status is still 3, and the message is the
# output's alone.
. "$SCN_SRCDIR/tests/lib.sh"

cd "$work" || exit 99
printf 'sphere { <0, 0, 0>, -1 }\n' >bad.scn
printf 'camera { resolution 8, 6 }\nsphere { <0, 0, 5>, 1 }\n' >good.scn

expect_status 3 "$SCN" render bad.scn -o nodir/out.png
only_line "$work/err" "scn: cannot write 'nodir/out.png': No such file or directory"
expect_status 3 "$SCN" render bad.scn -o bad.scn/out.png
only_line "$work/err" "scn: cannot write 'bad.scn/out.png': Not a directory"
mkdir dir.png
expect_status 3 "$SCN" render bad.scn -o dir.png
only_line "$work/err" "scn: cannot write 'dir.png': Is a directory"

expect_status 3 "$SCN" diff missing-a.png missing-b.png --heatmap nodir/heat.png
only_line "$work/err" "scn: cannot write 'nodir/heat.png': No such file or directory"

expect_status 3 "$SCN" converge bad.scn --no-pov --csv nodir/t.csv
only_line "$work/err" "scn: cannot write 'nodir/t.csv': No such file or directory"
expect_status 3 "$SCN" converge bad.scn --no-pov --plot nodir/t.svg
only_line "$work/err" "scn: cannot write 'nodir/t.svg': No such file or directory"

# scn pov does no long work before it writes; the scene's errors come first
expect_status 3 "$SCN" pov good.scn -o nodir/x.pov
only_line "$work/err" "scn: cannot write 'nodir/x.pov': No such file or directory"

# a folder without write permission (root may write anyway)
mkdir ro && chmod 555 ro
if ! touch ro/probe 2>/dev/null; then
	expect_status 3 "$SCN" render bad.scn -o ro/out.png
	only_line "$work/err" "scn: cannot write 'ro/out.png': Permission denied"
	expect_status 3 "$SCN" diff missing-a.png missing-b.png --heatmap ro/heat.png
	only_line "$work/err" "scn: cannot write 'ro/heat.png': Permission denied"
	expect_status 3 "$SCN" converge bad.scn --no-pov --csv ro/t.csv
	only_line "$work/err" "scn: cannot write 'ro/t.csv': Permission denied"
	expect_status 3 "$SCN" pov good.scn -o ro/x.pov
	only_line "$work/err" "scn: cannot write 'ro/x.pov': Permission denied"
else
	echo "running as root: the read-only folder is writable, its cases are skipped"
fi
chmod 755 ro

# none of it left a file behind
leftover=$(find . -name '.scn-*' -o -name 'out.png' -o -name '*.csv' -o -name '*.svg' -o -name 'x.pov' -o -name 'heat.png')
[ -z "$leftover" ] || fail "files left: $leftover"
finish

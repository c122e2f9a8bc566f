# commands.sh: the scn command line: help, version, exit statuses of LANGUAGE.md section 8.
. "$SCN_SRCDIR/tests/lib.sh"

expect_status 0 "$SCN" --help
expect_grep "$work/out" '^usage: scn COMMAND'
expect_status 0 "$SCN" --version
expect_grep "$work/out" '^scn [0-9]+\.[0-9]+\.[0-9]+$'
expect_status 0 "$SCN" help check
expect_grep "$work/out" '^usage: scn check'
expect_status 2 "$SCN"
expect_status 2 "$SCN" frobnicate
expect_grep "$work/err" "unknown command 'frobnicate'"
expect_status 2 "$SCN" help frobnicate
expect_status 2 "$SCN" check
expect_grep "$work/err" 'no scene given'
expect_status 2 "$SCN" check --bogus x.scn
expect_grep "$work/err" "unknown option '--bogus'"

# unreadable scene: status 3 with the OS reason
expect_status 3 "$SCN" check "$work/missing.scn"
expect_grep "$work/err" "cannot read '.*missing.scn': No such file or directory"
expect_status 3 "$SCN" check "$work"
expect_grep "$work/err" 'Is a directory'

# standard input
printf 'sphere { <0,0,0>, 1 }\n' >"$work/ok.scn"
expect_status 0 "$SCN" check - <"$work/ok.scn"
printf 'sphere { <0,0,0>, -1 }\n' >"$work/in.scn"
expect_status 1 "$SCN" check - <"$work/in.scn"
expect_grep "$work/err" "^<stdin>:1:19: error: a sphere's radius must be positive, not -1$"

# a clean scene prints nothing; errors exit 1 and print nothing on stdout
expect_status 0 "$SCN" check "$SCN_SRCDIR/examples/whitted.scn"
[ -s "$work/err" ] && fail "whitted.scn is not clean: $(cat "$work/err")"
expect_status 1 "$SCN" check --dump "$work/in.scn"
[ -s "$work/out" ] && fail "--dump printed a scene that has errors"
finish

# lib.sh: helpers for the .sh tests, sourced by them. $SCN is the scn under test.
set -u
: "${SCN:?run these tests through make check}"
: "${SCN_SRCDIR:?run these tests through make check}"
fails=0
work=$(mktemp -d "${TMPDIR:-/tmp}/scn-sh.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT

fail() {
	echo "FAIL: $*"
	fails=$((fails + 1))
}

# expect_status WANT CMD...: runs CMD, output in $work/out and $work/err.
expect_status() {
	want=$1
	shift
	"$@" >"$work/out" 2>"$work/err"
	got=$?
	[ "$got" -eq "$want" ] || { fail "'$*' exited $got, expected $want"; cat "$work/err"; }
}

# expect_grep FILE PATTERN: FILE contains a line matching PATTERN (grep -E).
expect_grep() {
	grep -Eq -- "$2" "$1" || { fail "$1 lacks /$2/"; sed 's/^/  | /' "$1" | head -20; }
}

# only_line FILE LINE: FILE holds exactly LINE
only_line() {
	[ "$(cat "$1")" = "$2" ] || { fail "expected only '$2' in $1"; sed 's/^/  | /' "$1"; }
}

finish() {
	[ "$fails" -eq 0 ] && exit 0
	echo "$fails failure(s)"
	exit 1
}

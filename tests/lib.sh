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

# usage_error MESSAGE CMD ARGS...: CMD ARGS exits 2, its first line on standard error is
# "scn: MESSAGE", the usage of CMD follows, and nothing is on standard output
usage_error() {
	msg=$1 cmd=$2
	shift
	expect_status 2 "$SCN" "$@"
	[ "$(head -n 1 "$work/err")" = "scn: $msg" ] ||
		{ fail "'$*': expected 'scn: $msg'"; sed 's/^/  | /' "$work/err"; }
	sed -n 2p "$work/err" | grep -q "^usage: scn $cmd" || fail "'$*' did not show the usage of $cmd"
	[ -s "$work/out" ] && fail "'$*' printed on standard output"
}

# same_bytes A B WHAT: the files are identical
same_bytes() {
	cmp -s "$1" "$2" || fail "$3: $1 and $2 differ"
}

# no_temp WHAT: no temporary file of an atomic writer is left in the current directory
no_temp() {
	leftover=$(ls -a | grep '\.tmp$')
	[ -z "$leftover" ] || { fail "$1: temporary files left: $leftover"; rm -f -- $leftover; }
}

finish() {
	[ "$fails" -eq 0 ] && exit 0
	echo "$fails failure(s)"
	exit 1
}

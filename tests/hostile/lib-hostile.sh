# lib-hostile.sh: helpers for the hostile-input tests, sourced after tests/lib.sh.
# Every run of $SCN is capped in time (timeout) and in address space (ulimit -v), so that
# a hang or a runaway allocation fails the test instead of the machine. AddressSanitizer
# reserves terabytes of address space and runs slower: with a sanitizer build (or
# SCN_SANITIZED=1) the address-space cap is left out and the time caps are multiplied.
# Inputs are generated into $work at run time; nothing big is committed.

# Address-space cap in KiB (ulimit -v); SCN_HOSTILE_VMEM overrides.
vmem=${SCN_HOSTILE_VMEM:-2000000}
# Multiplier of every time cap; SCN_HOSTILE_SLOW overrides.
slow=${SCN_HOSTILE_SLOW:-1}

# SCN_SANITIZED: yes or no from configure (tests/local.mk exports it), 1 or 0 by hand
sanitized=${SCN_SANITIZED:-}
case $sanitized in no | 0) sanitized= ;; esac
if [ -z "$sanitized" ] && nm "$SCN" 2>/dev/null | grep -q '__asan_init\|__ubsan_handle'; then
	sanitized=1
fi
# without nm: a sanitizer build does not even start under the address-space cap
if [ -z "$sanitized" ] && ! sh -c 'ulimit -v "$1" && "$2" --version' sh "$vmem" "$SCN" >/dev/null 2>&1; then
	sanitized=1
fi
if [ -n "$sanitized" ]; then
	vmem=unlimited
	slow=${SCN_HOSTILE_SLOW:-6}
fi

command -v timeout >/dev/null 2>&1 || { echo "SKIP: no timeout(1)"; exit 77; }
command -v python3 >/dev/null 2>&1 || { echo "SKIP: no python3 to generate the inputs"; exit 77; }

# capped SECONDS CMD...: runs CMD under the caps; 124 means it timed out.
capped() {
	c_secs=$(($1 * slow))
	shift
	(
		[ "$vmem" = unlimited ] || ulimit -v "$vmem" || exit 99
		exec timeout -k 5 "$c_secs" "$@"
	)
}

# expect_capped WANT SECONDS CMD...: expect_status with the caps, saying why a run died.
expect_capped() {
	h_want=$1
	h_secs=$2
	shift 2
	h_start=$(date +%s)
	capped "$h_secs" "$@" >"$work/out" 2>"$work/err"
	h_got=$?
	h_took=$(($(date +%s) - h_start))
	if [ "$h_got" -ne "$h_want" ]; then
		case $h_got in
		124|137) h_why="timed out after $((h_secs * slow)) s" ;;
		4) h_why="ran out of memory (status 4) under ulimit -v $vmem" ;;
		13[0-9]|1[4-9][0-9]) h_why="killed by signal $((h_got - 128))" ;;
		*) h_why="exited $h_got" ;;
		esac
		fail "'$*' $h_why, expected status $h_want"
		head -c 2000 "$work/err" | sed 's/^/  | /'
	fi
	echo "  '$*': status $h_got in ${h_took}s" | cut -c1-160
}

# expect_small FILE BYTES: FILE holds at most BYTES bytes.
expect_small() {
	h_size=$(wc -c <"$1")
	[ "$h_size" -le "$2" ] || fail "$1 has $h_size bytes, more than $2"
}

# expect_count FILE PATTERN N: exactly N lines of FILE match PATTERN (grep -E).
expect_count() {
	h_n=$(grep -Ec -- "$2" "$1")
	[ "$h_n" -eq "$3" ] || { fail "$1 has $h_n lines matching /$2/, expected $3"; head -c 1500 "$1" | sed 's/^/  | /'; }
}

# expect_nothing_after_stop FILE: the "too many errors" line is there, and last.
expect_stopped() {
	expect_count "$1" ': error: ' 20
	tail -n 1 "$1" | grep -q '^scn: too many errors (more than 20), stopping$' ||
		{ fail "$1 does not end with the stop message"; tail -n 3 "$1" | sed 's/^/  | /'; }
}

# gen FILE PYTHON: writes FILE with the output of the python3 program (sys.stdout is
# binary-safe through sys.stdout.buffer).
gen() {
	python3 -c "$2" >"$1" || { fail "could not generate $1"; finish; }
}

#!/bin/sh
# replay.sh: replays the fuzzers' saved corpora (tests/fuzz/corpus/HARNESS/) and the
# reproducers of what they found (tests/fuzz/regress/HARNESS/) through each harness built
# with the normal compiler (replay_HARNESS, see local.mk), so that every finding stays
# fixed in every build: each file must give a clean run (exit 0: a bad file's error is
# only reported) within a time limit, and in the sanitizer build no sanitizer report.
. "$SCN_SRCDIR/tests/lib.sh"

bin=$(dirname "$SCN")/tests/fuzz
TMPDIR=$work      # the harnesses' temporary files, removed with it
export TMPDIR
# Out-of-memory findings were single allocations of gigabytes: in the sanitizer build
# one above 1 GiB is a report, as it was for libFuzzer, and not a quiet success.
ASAN_OPTIONS="max_allocation_size_mb=1024${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export ASAN_OPTIONS

for h in scene mesh png exr part; do
	set -- "$SCN_SRCDIR/tests/fuzz/corpus/$h"/*
	[ -f "$1" ] || { fail "no corpus for $h"; continue; }
	[ -d "$SCN_SRCDIR/tests/fuzz/regress/$h" ] && set -- "$@" "$SCN_SRCDIR/tests/fuzz/regress/$h"/*
	# all files in one run; if it fails, each file alone to name the culprits
	timeout 600 "$bin/replay_$h" "$@" 2>"$work/err" && continue
	for f in "$@"; do
		timeout 60 "$bin/replay_$h" "$f" 2>"$work/err" && continue
		fail "replay_$h ${f#"$SCN_SRCDIR"/}"
		head -n 20 "$work/err"
	done
done
finish

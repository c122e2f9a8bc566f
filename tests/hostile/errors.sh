# errors.sh: a thousand errors of each kind print exactly 20, then "scn: too many
# errors (more than 20), stopping"; warnings are not capped but cost linear time.
. "$SCN_SRCDIR/tests/lib.sh"
. "$SCN_SRCDIR/tests/hostile/lib-hostile.sh"

# expect_flood NAME PYTHON-LINE [FIRST LAST]: 1000 copies of a line, each one error; the
# errors printed are on lines FIRST (1) to LAST (20).
expect_flood() {
	gen "$work/$1.scn" "print('''$2\n''' * 1000)"
	expect_capped 1 10 "$SCN" check "$work/$1.scn"
	expect_stopped "$work/err"
	expect_small "$work/err" 20000
	# the first 20, in reading order
	grep ': error: ' "$work/err" | sed -n '1p;20p' | sed 's/^.*\.scn:\([0-9]*\):.*/\1/' | tr '\n' ' ' >"$work/lines"
	[ "$(cat "$work/lines")" = "${3:-1} ${4:-20} " ] || fail "$1: errors not on lines ${3:-1} to ${4:-20}: $(cat "$work/lines")"
}

expect_flood lex '@'
expect_flood lex_utf8 '\u00e9'
expect_flood syntax 'sphere { <0,0,0> 1 }'
expect_flood name 'sphere { <zz,0,0>, 1 }'
expect_flood type 'sphere { "s", 1 }'
expect_flood attribute 'light { position <0,0,0> radius 1 }'
expect_flood value 'sphere { <0,0,0>, -1 }'
expect_flood nonfinite 'sphere { <1/0,0,0>, 1 }'
expect_flood number 'sphere { <1e999,0,0>, 1 }'
expect_flood include 'include "missing.scn"'
# errors with notes: the notes of the 20 printed errors are printed, no others
expect_flood rebind 'let a = 1' 2 21
expect_count "$work/err" ': note: ' 20
expect_count "$work/err" ': error: ' 20

# recovery skips a statement that starts within three tokens of the last error, so
# this is one error (not a safety matter: the output stays small)
gen "$work/syntax_missing.scn" "print('let = 2\n' * 1000)"
expect_capped 1 10 "$SCN" check "$work/syntax_missing.scn"
expect_small "$work/err" 20000

# a thousand errors in one included file, included from a file that has its own
printf 'let a = zz\n' >"$work/inc_first.scn"
gen "$work/inc_body.scn" "print('sphere { <0,0,0> 1 }\n' * 1000)"
printf 'include "inc_body.scn"\nsphere { <0,0,0>, -1 }\n' >>"$work/inc_first.scn"
expect_capped 1 10 "$SCN" check "$work/inc_first.scn"
expect_stopped "$work/err"
expect_count "$work/err" '^In file included from .*inc_first.scn:2:9:$' 19

# a thousand errors in a loop body that runs a thousand times: one report per place
gen "$work/loop.scn" "print('for i in 0 .. 1000 {\n' + 'sphere { <0,0,0>, i - 1000 }\n' * 10 + '}')"
expect_capped 1 10 "$SCN" check "$work/loop.scn"
expect_count "$work/err" ': error: ' 10
expect_count "$work/err" ': note: when i = 0$' 10

# 100000 warnings, in linear time: the first 100 in reading order, then their count
gen "$work/warnings.scn" "print('\n'.join('let v%d = 1' % i for i in range(100000)))"
expect_capped 0 20 "$SCN" check "$work/warnings.scn"
expect_count "$work/err" ': warning: ' 100
head -n 1 "$work/err" | grep -q "warnings.scn:1:5: warning: 'v0' is never used$" ||
	fail "warnings not in reading order: $(head -n 1 "$work/err")"
tail -n 4 "$work/err" | head -n 1 | grep -q "warnings.scn:100:5: warning: 'v99' is never used$" ||
	fail "not the first 100 warnings: $(tail -n 4 "$work/err" | head -n 1)"
tail -n 1 "$work/err" | grep -q '^scn: 99900 more warnings not shown$' ||
	fail "no count of the warnings not shown: $(tail -n 1 "$work/err")"
gen "$work/materials.scn" "print('\n'.join('material m%d { }' % i for i in range(100000)))"
expect_capped 0 20 "$SCN" check "$work/materials.scn"
expect_count "$work/err" ': warning: ' 100
# warnings and then 21 errors: the warnings before the stop are printed
gen "$work/mixed.scn" "print('let w = 1\n' + 'let v = zz\n' * 21)"
expect_capped 1 10 "$SCN" check "$work/mixed.scn"
expect_stopped "$work/err"
finish

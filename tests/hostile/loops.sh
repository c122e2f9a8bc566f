# loops.sh: for loops run at most 10^7 iterations in all (LANGUAGE.md section 6), counted
# across sequential, nested and included loops; the check comes before the work.
. "$SCN_SRCDIR/tests/lib.sh"
. "$SCN_SRCDIR/tests/hostile/lib-hostile.sh"

limit_msg='error: the for loops would run more than 10000000 iterations in all$'

# exactly 10^7 is allowed, one more is not
printf 'for i in 0 .. 10000000 { }\n' >"$work/at_limit.scn"
expect_capped 0 20 "$SCN" check "$work/at_limit.scn"
printf 'for i in 0 .. 10000000 { let a = i * 2 }\n' >"$work/at_limit_body.scn"
expect_capped 0 30 "$SCN" check "$work/at_limit_body.scn"
printf 'for i in 0 .. 10000001 { }\n' >"$work/over.scn"
expect_capped 1 5 "$SCN" check "$work/over.scn"
expect_grep "$work/err" "^.*over.scn:1:10: $limit_msg"
expect_count "$work/err" ': error: ' 1
printf 'for i in -10000000 .. 1 { }\n' >"$work/over_neg.scn"
expect_capped 1 5 "$SCN" check "$work/over_neg.scn"
expect_grep "$work/err" "$limit_msg"
printf 'for i in 0 .. 9007199254740992 { sphere { <i,0,0>, 1 } }\n' >"$work/over_2p53.scn"
expect_capped 1 5 "$SCN" check "$work/over_2p53.scn"
expect_grep "$work/err" "$limit_msg"

# bounds that are not whole numbers within 2^53 are errors, before any iteration
for bound in 1e300 -1e300 9007199254740994 0.5 '1/3'; do
	printf 'for i in 0 .. %s { sphere { <i,0,0>, 1 } }\n' "$bound" >"$work/bound.scn"
	expect_capped 1 5 "$SCN" check "$work/bound.scn"
	expect_grep "$work/err" "error: a for loop's end must be a whole number from -2\\^53 to 2\\^53, not "
done
printf 'for i in 0 .. 1/0 { }\nfor j in sqrt(-1) .. 2 { }\n' >"$work/bound_nan.scn"
expect_capped 1 5 "$SCN" check "$work/bound_nan.scn"
expect_grep "$work/err" 'error: division by zero'
expect_grep "$work/err" 'error: sqrt of a negative number'
printf 'for i in 10 .. -1e15 { sphere { <i,0,0>, 1 } }\n' >"$work/empty.scn"
expect_capped 0 5 "$SCN" check "$work/empty.scn"

# iterations add up across sequential loops ...
printf 'for i in 0 .. 6000000 { }\nfor j in 0 .. 6000000 { }\n' >"$work/sequential.scn"
expect_capped 1 20 "$SCN" check "$work/sequential.scn"
expect_grep "$work/err" "^.*sequential.scn:2:10: $limit_msg"
expect_count "$work/err" ': error: ' 1

# ... and across the runs of a nested loop, which stop at the first run that would pass
printf 'for i in 0 .. 10000 { for j in 0 .. 1001 { } }\n' >"$work/nested.scn"
expect_capped 1 20 "$SCN" check "$work/nested.scn"
expect_grep "$work/err" "^.*nested.scn:1:32: $limit_msg"
expect_grep "$work/err" 'note: when i = 9980$'
expect_count "$work/err" ': error: ' 1
printf 'for i in 0 .. 100000 { for j in 0 .. 100000 { for k in 0 .. 100000 { let a = i + j + k } } }\n' \
	>"$work/nested3.scn"
expect_capped 1 20 "$SCN" check "$work/nested3.scn"
expect_grep "$work/err" "$limit_msg"
expect_count "$work/err" ': error: ' 1
# twenty levels of 0 .. 3 are 3^20 = 3.5e9 iterations
gen "$work/nested20.scn" "print(''.join('for i%d in 0 .. 3 {\n' % k for k in range(20)) + 'let a = 1\n' + '}'*20)"
expect_capped 1 20 "$SCN" check "$work/nested20.scn"
expect_grep "$work/err" "$limit_msg"
expect_count "$work/err" ': error: ' 1

# ... and through includes
printf 'for j in 0 .. 4000 { }\n' >"$work/inner.scn"
printf 'for i in 0 .. 4000 { include "inner.scn" }\n' >"$work/outer.scn"
expect_capped 1 20 "$SCN" check "$work/outer.scn"
expect_grep "$work/err" "^.*inner.scn:1:10: $limit_msg"

# an error in a body that runs a million times is reported once, with the loop's value
printf 'for i in 0 .. 1000000 { sphere { <i,0,0>, 999999 - i } }\n' >"$work/error_once.scn"
expect_capped 1 30 "$SCN" check "$work/error_once.scn"
expect_count "$work/err" ': error: ' 1
expect_grep "$work/err" "error: a sphere's radius must be positive, not 0$"
expect_grep "$work/err" 'note: when i = 999999$'

# 999 nested loops of one iteration each: the for nesting allowed by the bracket limit
gen "$work/deep.scn" "print(''.join('for i%d in 0 .. 1 {\n' % k for k in range(998)) + 'sphere { <i0,0,0>, 1 }\n' + '}'*998)"
expect_capped 0 10 "$SCN" check "$work/deep.scn"

# a loop multiplies its body's work: the evaluation as a whole has a budget of steps
gen "$work/steps.scn" "print('for i in 0 .. 10000000 { let a = max(' + ', '.join(['i'] * 60) + ') }')"
expect_capped 1 30 "$SCN" check "$work/steps.scn"
expect_grep "$work/err" ":1:[0-9]+: error: the scene takes more than 500000000 evaluation steps \\(its loops and calls do too much work\\)$"
# ... and of objects (10^7 two-sphere iterations stop at 10^7 objects; about 1 GB before
# the error, too much for the sanitizer build's shadow memory)
if [ -z "$sanitized" ]; then
	gen "$work/objects.scn" "print('for i in 0 .. 10000000 { sphere { <i,0,0>, 1 } sphere { <i,1,0>, 1 } }')"
	expect_capped 1 30 "$SCN" check "$work/objects.scn"
	expect_grep "$work/err" ": error: the scene makes more than 10000000 objects$"
fi
finish

# language.sh: the second half of the language against hostile scenes (LANGUAGE.md 10):
# recursion stops at 256 calls, the arrays and strings alive at once at 10^7 elements,
# exponential expansion at the evaluation-step limit, each with a clear error that
# shows the calls on the way; a million top-level calls and definitions stream in
# bounded memory.
. "$SCN_SRCDIR/tests/lib.sh"
. "$SCN_SRCDIR/tests/hostile/lib-hostile.sh"

# recursion without end, in a function and in a macro: 256 calls, one error with the
# innermost and outermost five calls as notes and the rest counted
printf 'def down(n) = down(n + 1)\nlet a = down(0)\n' >"$work/deep_fn.scn"
expect_capped 1 5 "$SCN" check "$work/deep_fn.scn"
expect_grep "$work/err" "^.*deep_fn.scn:1:15: error: calls nested more than 256 deep \\(does a recursion end\\?\\)$"
expect_count "$work/err" ': error: ' 1
expect_count "$work/err" "note: in call to 'down'" 10
expect_grep "$work/err" "note: in call to 'down' \\(after 246 calls not shown\\)$"
expect_grep "$work/err" "^.*deep_fn.scn:2:9: note: in call to 'down'$"
printf 'def m(n) { sphere { <n, 0, 0>, 1 }  m(n + 1) }\nm(0)\n' >"$work/deep_macro.scn"
expect_capped 1 5 "$SCN" check "$work/deep_macro.scn"
expect_grep "$work/err" "^.*deep_macro.scn:1:37: error: calls nested more than 256 deep"
expect_count "$work/err" ': error: ' 1
# 255 nested calls are fine
# a body that calls itself twice without end: the depth's error stops the evaluation,
# where going on after the failing call would double the calls at each level back up
printf 'def m(d) {\n  m(2)\n  m(2)\n}\nm(2)\nsphere { <0, 0, 0>, 1 }\n' >"$work/deep_twice.scn"
expect_capped 1 5 "$SCN" check "$work/deep_twice.scn"
expect_grep "$work/err" "^.*deep_twice.scn:2:3: error: calls nested more than 256 deep"
expect_count "$work/err" ': error: ' 1
printf 'def m(n) { sphere { <n, 0, 0>, 1 }  if n < 255 { m(n + 1) } }\nm(1)\n' >"$work/deep_ok.scn"
expect_capped 0 5 "$SCN" check "$work/deep_ok.scn"

# recursion through bodies that nest 1000 deep: stopped by the stack's depth, not a crash
gen "$work/deep_body_fn.scn" "
print('def f(n) = n == 0 ? 0 : ' + '1 + (' * 990 + 'f(n - 1)' + ')' * 990)
print('let a = f(255)')
print('sphere { <a, 0, 0>, 1 }')
"
expect_capped 1 20 "$SCN" check "$work/deep_body_fn.scn"
expect_grep "$work/err" "error: calls nested too deep for the stack: each holds deeply nested expressions or blocks$"
expect_count "$work/err" ': error: ' 1
gen "$work/deep_body_macro.scn" "
print('def m(n) {')
print('if n > 0 { ' * 900 + 'm(n - 1)' + ' }' * 900)
print('}')
print('m(255)')
"
expect_capped 1 20 "$SCN" check "$work/deep_body_macro.scn"
expect_grep "$work/err" "error: calls nested too deep for the stack"

# arrays that double: stopped at 10^7 elements alive, before they are made
printf 'def grow(xs, k) = k == 0 ? xs : grow(xs + xs, k - 1)\nlet big = grow([1], 40)\nsphere { <len(big), 0, 0>, 1 }\n' \
	>"$work/array_doubling.scn"
expect_capped 1 20 "$SCN" check "$work/array_doubling.scn"
expect_grep "$work/err" "error: the scene's arrays and strings would hold more than 10000000 elements at once$"
expect_grep "$work/err" "note: in call to 'grow'"
expect_count "$work/err" ': error: ' 1
# and strings
printf 'def grow(s, k) = k == 0 ? s : grow(s + s, k - 1)\nlet big = grow("ab", 60)\nsphere { <len(big), 0, 0>, 1 }\n' \
	>"$work/string_doubling.scn"
expect_capped 1 20 "$SCN" check "$work/string_doubling.scn"
expect_grep "$work/err" "error: the scene's arrays and strings would hold more than 10000000 elements at once$"
# what a loop iteration makes is released after it: 10^5 iterations of 1000 elements each
printf 'for i in 0 .. 100000 { let xs = [i, i, i, i, i, i, i, i, i, i]  let ys = xs + xs + xs + xs + xs + xs + xs + xs + xs + xs\n  let zs = ys + ys + ys + ys + ys + ys + ys + ys + ys + ys  let s = str(i) + "x"  if len(zs) != 1000 { sphere { <0, 0, 0>, len(s) } } }\n' \
	>"$work/released.scn"
expect_capped 0 60 "$SCN" check "$work/released.scn"

# exponential expansion: a macro that calls itself twice, stopped by the step limit with
# the calls on the way
printf 'def m(d) { if d > 0 { m(d - 1)  m(d - 1) } }\nm(100)\n' >"$work/expand_macro.scn"
expect_capped 1 120 "$SCN" check "$work/expand_macro.scn"
expect_grep "$work/err" "error: the scene takes more than 500000000 evaluation steps \\(its loops and calls do too much work\\)$"
expect_grep "$work/err" "^.*expand_macro.scn:2:1: note: in call to 'm'$"
expect_count "$work/err" ': error: ' 1

# a million top-level macro calls, and 10^5 definitions, stream in bounded memory (the
# address-space cap) and a few seconds
gen "$work/calls.scn" "
print('def ball(x, y) { sphere { <x, y, 0>, 0.4 } }')
for i in range(1000000):
    print('ball(%d, %d)' % (i % 1000, i // 1000))
"
expect_capped 0 60 "$SCN" check "$work/calls.scn"
[ -s "$work/err" ] && fail "calls.scn is not clean: $(head -c 500 "$work/err")"
gen "$work/defs.scn" "
for i in range(100000):
    print('def f%d(x) = x + %d' % (i, i))
print('sphere { <f99999(1), f0(2), 0>, 1 }')
"
expect_capped 0 60 "$SCN" check "$work/defs.scn"
expect_grep "$work/err" "warning: function 'f1' is never used"

finish

# nesting.sh: deep nesting stops at LANGUAGE.md's limit of 1000 with a clear error, in
# bounded time and memory: brackets of each kind, unary minus, long operator chains,
# calls, component selection, for loops.
. "$SCN_SRCDIR/tests/lib.sh"
. "$SCN_SRCDIR/tests/hostile/lib-hostile.sh"

# brackets: 1000 deep is allowed; 1001 and 100000 are one error and the end of the parse
gen "$work/paren1000.scn" "print('let x = ' + '('*1000 + '1' + ')'*1000 + '\nsphere { <x,0,0>, 1 }')"
expect_capped 0 10 "$SCN" check "$work/paren1000.scn"
for n in 1001 100000; do
	gen "$work/paren$n.scn" "print('let x = ' + '('*$n + '1' + ')'*$n)"
	expect_capped 1 10 "$SCN" check "$work/paren$n.scn"
	expect_grep "$work/err" "^paren$n.scn:1:1009: error: brackets nested more than 1000 deep$|/paren$n.scn:1:1009: error: brackets nested more than 1000 deep$"
	expect_count "$work/err" ': error: ' 1
	expect_small "$work/err" 2000

	gen "$work/vec$n.scn" "print('let x = ' + '<1, 1, '*$n + '1' + '>'*$n)"
	expect_capped 1 10 "$SCN" check "$work/vec$n.scn"
	expect_grep "$work/err" ':1:[0-9]+: error: brackets nested more than 1000 deep$'
	expect_count "$work/err" ': error: ' 1

	gen "$work/lt$n.scn" "print('let x = ' + '<'*$n + '1')"
	expect_capped 1 10 "$SCN" check "$work/lt$n.scn"
	expect_grep "$work/err" ':1:1009: error: brackets nested more than 1000 deep$'
	expect_count "$work/err" ': error: ' 1

	gen "$work/brace$n.scn" "print('{'*$n)"
	expect_capped 1 10 "$SCN" check "$work/brace$n.scn"
	expect_grep "$work/err" ':1:1001: error: brackets nested more than 1000 deep$'
	expect_small "$work/err" 2000

	gen "$work/brace_mat$n.scn" "print('sphere { <0,0,0>, 1 material ' + '{ '*$n)"
	expect_capped 1 10 "$SCN" check "$work/brace_mat$n.scn"
	expect_grep "$work/err" 'error: brackets nested more than 1000 deep$'
	expect_small "$work/err" 2000

	gen "$work/call$n.scn" "print('let x = ' + 'sqrt('*$n + '1' + ')'*$n)"
	expect_capped 1 10 "$SCN" check "$work/call$n.scn"
	expect_grep "$work/err" 'error: brackets nested more than 1000 deep$'

	# closers without openers: a syntax error, then recovery to the end, in linear time
	gen "$work/close$n.scn" "print('let x = 1 ' + ')}>'*$n)"
	expect_capped 1 10 "$SCN" check "$work/close$n.scn"
	expect_grep "$work/err" "error: unexpected '\\)'"
	expect_small "$work/err" 20000
done

# a mess of 999 open brackets followed by five million closers that match none of them
gen "$work/unmatched.scn" "print('let x = ' + '<'*999 + ')'*5000000)"
expect_capped 1 10 "$SCN" check "$work/unmatched.scn"
expect_grep "$work/err" "error: unexpected '\\)'"
expect_small "$work/err" 20000

# unary minus nests without brackets
# (999 minus signs and the number are 1000 levels)
gen "$work/neg999.scn" "print('let x = ' + '-'*999 + '1\nsphere { <x,0,0>, 1 }')"
expect_capped 0 10 "$SCN" check "$work/neg999.scn"
for n in 1000 100000 5000000; do
	gen "$work/neg$n.scn" "print('let x = ' + '-'*$n + '1')"
	expect_capped 1 10 "$SCN" check "$work/neg$n.scn"
	expect_grep "$work/err" ':1:[0-9]+: error: expression nested more than 1000 deep'
	expect_small "$work/err" 20000
done
gen "$work/negsp.scn" "print('let x = ' + '- '*100000 + '1')"
expect_capped 1 10 "$SCN" check "$work/negsp.scn"
expect_grep "$work/err" 'error: expression nested more than 1000 deep'

# long chains of binary operators nest as deep as they are long
gen "$work/sum1000.scn" "print('let x = ' + '+'.join(['1']*1000) + '\nsphere { <x,0,0>, 1 }')"
expect_capped 0 10 "$SCN" check "$work/sum1000.scn"
for op in + - '*' /; do
	gen "$work/chain.scn" "print('let x = ' + '$op'.join(['1']*100000))"
	expect_capped 1 10 "$SCN" check "$work/chain.scn"
	expect_grep "$work/err" '^.*chain.scn:1:9: error: expression nested more than 1000 deep$'
	expect_small "$work/err" 20000
done
gen "$work/member.scn" "print('let x = <1,2,3>' + '.x'*100000)"
expect_capped 1 10 "$SCN" check "$work/member.scn"
expect_grep "$work/err" 'error: expression nested more than 1000 deep'
expect_small "$work/err" 20000

# very wide is not deep: a call with a million arguments, a vector list of 200000
gen "$work/wide.scn" "print('let x = max(' + ','.join(['1']*1000000) + ')\nsphere { <x,0,0>, 1 }')"
expect_capped 0 20 "$SCN" check "$work/wide.scn"
[ -s "$work/err" ] && fail "wide.scn is not clean: $(head -c 300 "$work/err")"
gen "$work/wide_vec.scn" "print('let x = min(' + ','.join(['<1,2,3>']*200000) + ')\nsphere { x, 1 }')"
expect_capped 0 20 "$SCN" check "$work/wide_vec.scn"

# for loops: 999 nested loops are fine, more are 'brackets nested more than 1000 deep'
gen "$work/for999.scn" "print(''.join('for i%d in 0 .. 1 {\n' % k for k in range(998)) + 'let a = 1 sphere { <a,0,0>, 1 }\n' + '}'*998)"
expect_capped 0 10 "$SCN" check "$work/for999.scn"
gen "$work/for100k.scn" "print(''.join('for i%d in 0 .. 2 {\n' % k for k in range(100000)) + '}'*100000)"
expect_capped 1 10 "$SCN" check "$work/for100k.scn"
expect_grep "$work/err" '^.*for100k.scn:1001:21: error: brackets nested more than 1000 deep$'
expect_count "$work/err" ': error: ' 1
finish

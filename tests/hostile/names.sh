# names.sh: very long names and strings, many names, names built to collide in a hash
# table, and "did you mean" searches over many names, all in bounded time.
. "$SCN_SRCDIR/tests/lib.sh"
. "$SCN_SRCDIR/tests/hostile/lib-hostile.sh"

# a name of a million characters: bound, used, misspelt, unused
gen "$work/long_name.scn" "n = 'a' * 1000000; print('let %s = 1\nsphere { <%s, 0, 0>, 1 }' % (n, n))"
expect_capped 0 10 "$SCN" check "$work/long_name.scn"
gen "$work/long_unknown.scn" "n = 'a' * 1000000; print('let %sb = 1\nsphere { <%sc, 0, 0>, 1 }' % (n, n))"
expect_capped 1 10 "$SCN" check "$work/long_unknown.scn"
expect_grep "$work/err" "error: unknown name 'aaaaaaaaaa"
expect_count "$work/err" ': error: ' 1
gen "$work/long_material.scn" "n = 'm' * 1000000; print('sphere { <0, 0, 0>, 1 material %s }' % n)"
expect_capped 1 10 "$SCN" check "$work/long_material.scn"
expect_grep "$work/err" "error: unknown material 'mmmmmmmmmm"
gen "$work/long_attr.scn" "print('sphere { <0, 0, 0>, 1 %s 1 }' % ('r' * 1000000))"
expect_capped 1 10 "$SCN" check "$work/long_attr.scn"
expect_grep "$work/err" "error: unknown attribute 'rrrrrrrrrr"
gen "$work/long_fn.scn" "print('let x = %s(1)' % ('f' * 1000000))"
expect_capped 1 10 "$SCN" check "$work/long_fn.scn"
expect_grep "$work/err" "error: unknown function 'ffffffffff"

# a string of a million characters: a file name too long for the system
gen "$work/long_include.scn" "print('include \"%s\"' % ('i' * 1000000))"
expect_capped 1 10 "$SCN" check "$work/long_include.scn"
expect_grep "$work/err" "error: cannot read included file 'iiiiiiiiii.*': File name too long$"
gen "$work/long_mesh.scn" "print('mesh { \"%s\" }' % ('o' * 1000000))"
expect_capped 1 10 "$SCN" check "$work/long_mesh.scn"
expect_grep "$work/err" "error: cannot read mesh file 'oooooooooo.*': File name too long$"
gen "$work/long_escapes.scn" "print('mesh { \"' + '\\\\\\\\' * 500000 + '\\\\\"' * 100000 + '\" }')"
expect_capped 1 10 "$SCN" check "$work/long_escapes.scn"
expect_grep "$work/err" "error: cannot read mesh file"
gen "$work/long_bad_escapes.scn" "print('mesh { \"' + '\\\\q' * 500000 + '\" }')"
expect_capped 1 10 "$SCN" check "$work/long_bad_escapes.scn"
expect_stopped "$work/err"
expect_small "$work/err" 100000
gen "$work/long_unterminated.scn" "print('mesh { \"' + 's' * 1000000)"
expect_capped 1 10 "$SCN" check "$work/long_unterminated.scn"
expect_grep "$work/err" 'error: unterminated string'
expect_small "$work/err" 5000

# 200000 names, each used by the next
gen "$work/many_names.scn" "
print('let v0 = 1')
for i in range(1, 200000):
    print('let v%d = v%d + 1' % (i, i - 1))
print('sphere { <v199999, 0, 0>, 1 }')"
expect_capped 0 10 "$SCN" check "$work/many_names.scn"
[ -s "$work/err" ] && fail "many_names.scn is not clean: $(head -c 300 "$work/err")"

# names that collide in the hash h * 33 + c ('az' and 'bY' hash alike, so do all the
# 2^17 names made of 17 such pairs): a lookup must not scan them all
gen "$work/collide.scn" "
import itertools
names = [''.join(p) for p in itertools.product(('az', 'bY'), repeat=17)]
print('let %s = 1' % names[0])
for a, b in zip(names[1:], names):
    print('let %s = %s' % (a, b))
print('sphere { <%s, 0, 0>, 1 }' % names[-1])"
expect_capped 0 10 "$SCN" check "$work/collide.scn"
[ -s "$work/err" ] && fail "collide.scn is not clean: $(head -c 300 "$work/err")"

# 50000 names and 50000 unknown names in one statement: "did you mean" reads every
# name, but only for the errors that are printed
gen "$work/suggest.scn" "
for i in range(50000):
    print('let v%05d = 1' % i)
print('mesh { vertices { ' + ','.join('u%05d' % i for i in range(50000)) + ' } faces { <0, 1, 2> } }')"
expect_capped 1 10 "$SCN" check "$work/suggest.scn"
expect_grep "$work/err" "error: unknown name 'u00000'; did you mean 'v00000'\\?$"
expect_stopped "$work/err"
gen "$work/suggest_mat.scn" "
for i in range(50000):
    print('material m%05d { }' % i)
print('mesh { \"x.obj\" material n00000 }')
print('sphere { <0,0,0>, 1 material { like q00001 } }' * 50000)"
expect_capped 1 10 "$SCN" check "$work/suggest_mat.scn"
expect_grep "$work/err" "error: unknown material 'n00000'; did you mean 'm00000'\\?$"
expect_stopped "$work/err"

# min and max take any number of arguments: a million, and a vector after the 64th
gen "$work/many_args.scn" "print('let x = max(' + ','.join(['1'] * 1000000) + ')\nsphere { <x,0,0>, 1 }')"
expect_capped 0 20 "$SCN" check "$work/many_args.scn"
gen "$work/args_vec.scn" "print('let v = min(' + ','.join(['5'] * 70) + ', <1, 2, 3>, 9)\nsphere { v, 1 }')"
expect_capped 0 5 "$SCN" check --dump "$work/args_vec.scn"
expect_grep "$work/out" '^sphere 0 center <1, 2, 3> radius 1 '
finish

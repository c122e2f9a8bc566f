# big.sh: big valid scenes check clean in a few seconds and bounded memory; big invalid
# ones stop after 20 errors with small output; running out of memory is status 4.
. "$SCN_SRCDIR/tests/lib.sh"
. "$SCN_SRCDIR/tests/hostile/lib-hostile.sh"

# 100000 spheres with inline materials, about 10 MB
gen "$work/spheres.scn" "
import random
r = random.Random(1)
print('camera { location <0, 5, -40> look_at <0, 0, 0> }')
print('light { position <10, 20, -10> }')
print('material m { diffuse <0.5, 0.6, 0.7> specular 0.3 }')
for i in range(100000):
    x, y, z = (r.uniform(-50, 50) for k in range(3))
    if i % 2:
        print('sphere { <%.6f, %.6f, %.6f>, %.6f material { diffuse <%.4f, %.4f, %.4f> reflect 0.1 } }'
              % (x, y, z, r.uniform(0.01, 1), r.random(), r.random(), r.random()))
    else:
        print('sphere { <%.6f, %.6f, %.6f>, %.6f material m translate <1, 2, 3> }' % (x, y, z, r.uniform(0.01, 1)))
"
expect_capped 0 10 "$SCN" check "$work/spheres.scn"
[ -s "$work/err" ] && fail "spheres.scn is not clean: $(head -c 500 "$work/err")"

# the same on one 10 MB line
tr '\n' ' ' <"$work/spheres.scn" >"$work/oneline.scn"
expect_capped 0 10 "$SCN" check "$work/oneline.scn"
[ -s "$work/err" ] && fail "oneline.scn is not clean: $(head -c 500 "$work/err")"

# a 10 MB inline mesh on one line
gen "$work/mesh.scn" "
n = 150000
print('mesh { vertices { ' + ', '.join('<%d, %d, %d>' % (i % 97, i % 89, i % 83) for i in range(n)) + ' } '
      + 'faces { ' + ', '.join('<%d, %d, %d>' % (i, (i + 1) % n, (i + 2) % n) for i in range(n)) + ' } }')
"
expect_capped 0 20 "$SCN" check "$work/mesh.scn"

# 10 MB of comment, of whitespace, of one block comment: nothing to say
gen "$work/comment.scn" "print('// ' + 'x' * 10000000)"
expect_capped 0 5 "$SCN" check "$work/comment.scn"
[ -s "$work/err" ] && fail "comment.scn is not clean"
gen "$work/blank.scn" "print(' \t\n' * 3500000)"
expect_capped 0 5 "$SCN" check "$work/blank.scn"
gen "$work/block.scn" "print('/*' + '* / *\n' * 1500000 + '*/ sphere { <0,0,0>, 1 }')"
expect_capped 0 5 "$SCN" check "$work/block.scn"
# an unterminated block comment of 10 MB is one error
gen "$work/unterminated.scn" "print('sphere { <0,0,0>, 1 } /*' + '* / *\n' * 1500000)"
expect_capped 1 5 "$SCN" check "$work/unterminated.scn"
expect_grep "$work/err" '^.*unterminated.scn:1:23: error: unterminated comment$'
expect_count "$work/err" ': error: ' 1

# 100000 errors on one 2 MB line: 20 of them, each quoting a window of the line
gen "$work/errline.scn" "print('sphere { <0,0,0>, -1 } ' * 100000)"
expect_capped 1 10 "$SCN" check "$work/errline.scn"
expect_stopped "$work/err"
expect_small "$work/err" 20000
# and 100000 lines of them
gen "$work/errlines.scn" "print('sphere { <0,0,0>, -1 }\n' * 100000)"
expect_capped 1 10 "$SCN" check "$work/errlines.scn"
expect_stopped "$work/err"
expect_small "$work/err" 20000

# out of memory is status 4 with a message, not a crash (not under AddressSanitizer,
# which needs its own address space and aborts where malloc would return NULL)
if [ "$vmem" != unlimited ]; then
	vmem_saved=$vmem
	vmem=60000
	expect_capped 4 10 "$SCN" check "$work/spheres.scn"
	expect_grep "$work/err" '^scn: out of memory'
	expect_small "$work/err" 1000
	vmem=$vmem_saved
fi
finish

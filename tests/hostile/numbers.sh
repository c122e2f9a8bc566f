# numbers.sh: numbers too large to be doubles, results that overflow, huge digit
# strings, and values at and past the limits of section 6: max_depth 256, image
# pixels 2^28, 65536 a side, 65536 samples.
. "$SCN_SRCDIR/tests/lib.sh"
. "$SCN_SRCDIR/tests/hostile/lib-hostile.sh"

# expect_scene STATUS PATTERN TEXT: TEXT as a scene exits STATUS; with status 1 its
# first error matches PATTERN (grep -E).
expect_scene() {
	printf '%s\n' "$3" >"$work/n.scn"
	expect_capped "$1" 5 "$SCN" check "$work/n.scn"
	[ -z "$2" ] || expect_grep "$work/err" "$2"
}

too_large='error: the result is too large to be a number$'
expect_scene 1 "^.*n.scn:1:9: error: number '1e999999' is too large$" 'let x = 1e999999 sphere { <x,0,0>, 1 }'
expect_scene 1 "^.*n.scn:1:10: error: number '1e999999' is too large$" 'let x = -1e999999 sphere { <x,0,0>, 1 }'
expect_scene 0 '' 'let x = 1e-999999 sphere { <x,0,0>, 1 }'
expect_scene 0 '' 'let x = 0e99999999999999999999999 sphere { <x,0,0>, 1 }'
expect_scene 1 "$too_large" 'let x = 1e308 * 10 sphere { <x,0,0>, 1 }'
expect_scene 1 "$too_large" 'let x = 1e308 + 1e308 - 1e308 sphere { <x,0,0>, 1 }'
expect_scene 1 "$too_large" 'let x = pow(10, 400) sphere { <x,0,0>, 1 }'
expect_scene 1 "$too_large" 'let x = exp(1000) sphere { <x,0,0>, 1 }'
expect_scene 1 "$too_large" 'let x = dot(<1e200,1,1>, <1e200,1,1>) sphere { <x,0,0>, 1 }'
expect_scene 1 'error: division by zero$' 'let x = 1 / (1e-200 * 1e-200) sphere { <x,0,0>, 1 }'
expect_scene 1 "error: malformed number '1e5x'$" 'let x = 1e5x'
expect_scene 1 "error: malformed number '1e'$" 'let x = 1e'
expect_scene 1 "error: malformed number '1e\\+'$" 'let x = 1e+'

# a million digits
gen "$work/digits.scn" "print('let x = ' + '9' * 1000000 + '\nsphere { <x,0,0>, 1 }')"
expect_capped 1 10 "$SCN" check "$work/digits.scn"
expect_grep "$work/err" "error: number '9999999999999999999999999999999999999999' is too large$"
expect_small "$work/err" 5000
gen "$work/fraction.scn" "print('let x = 0.' + '0' * 1000000 + '1e1000001\nsphere { <x,0,0>, 1 }')"
expect_capped 0 10 "$SCN" check "$work/fraction.scn"
gen "$work/malformed.scn" "print('let x = 1e' + 'x' * 1000000)"
expect_capped 1 10 "$SCN" check "$work/malformed.scn"
expect_small "$work/err" 5000

# transforms that overflow
expect_scene 1 'error: the transforms make the object too large to be numbers$' \
	'sphere { <0,0,0>, 1 scale 1e200 scale 1e200 }'
expect_scene 1 'error: the transforms make the object too large to be numbers$' \
	'mesh { vertices { <0,0,0>, <1,0,0>, <0,1,0> } faces { <0,1,2> } translate <1e308,0,0> translate <1e308,0,0> }'

# the image: 65536 a side, 2^28 pixels
expect_scene 0 '' 'camera { resolution 65536, 4096 }'
expect_scene 1 'error: 65536 x 65536 is more pixels than the limit of 2\^28$' 'camera { resolution 65536, 65536 }'
expect_scene 1 'error: 16385 x 16385 is more pixels than the limit of 2\^28$' 'camera { resolution 16385, 16385 }'
expect_scene 1 'error: the width must be a whole number from 1 to 65536, not 65537$' 'camera { resolution 65537, 1 }'
expect_scene 1 'error: the width must be a whole number from 1 to 65536, not 1e\+300$' 'camera { resolution 1e300, 1e300 }'
expect_scene 1 'error: the height must be a whole number from 1 to 65536, not -1$' 'camera { resolution 1, -1 }'
expect_scene 1 'error: the width must be a whole number from 1 to 65536, not 0.5$' 'camera { resolution 0.5, 1 }'
expect_scene 1 'error: fov must be between 0 and 180 degrees' 'camera { fov 1e300 }'

# max_depth and samples
expect_scene 0 '' 'max_depth 256'
expect_scene 1 'error: max_depth must be a whole number from 1 to 256, not 257$' 'max_depth 257'
expect_scene 1 'error: max_depth must be a whole number from 1 to 256, not 1e\+300$' 'max_depth 1e300'
expect_scene 0 '' 'samples 65536'
expect_scene 1 'error: the sample count must be a whole number from 1 to 65536, not 65537$' 'samples 65537'
expect_scene 1 'error: the sample count must be a whole number from 1 to 65536, not 1e\+300$' 'samples { count 1e300 }'
expect_scene 1 'error: the seed must be a whole number from 0 to 2\^53, not 1e\+300$' 'samples { seed 1e300 }'
finish

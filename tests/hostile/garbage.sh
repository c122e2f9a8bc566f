# garbage.sh: files that are not scenes (random bytes, NUL bytes, an ELF program, a PNG
# image, invalid UTF-8, terminal escapes) give status 1 with at most 20 errors and the
# stop message, small output, and no control bytes on the terminal; one that is not text
# gives one error, at its first byte that is not.
. "$SCN_SRCDIR/tests/lib.sh"
. "$SCN_SRCDIR/tests/hostile/lib-hostile.sh"

# expect_garbage FILE: status 1, at most 20 errors, small stderr free of control bytes.
expect_garbage() {
	expect_capped 1 10 "$SCN" check "$1"
	g_errors=$(grep -c ': error: ' "$work/err")
	[ "$g_errors" -ge 1 ] && [ "$g_errors" -le 20 ] || fail "$1: $g_errors errors, expected 1 to 20"
	[ "$g_errors" -lt 20 ] || expect_stopped "$work/err"
	expect_small "$work/err" 100000
	[ -s "$work/out" ] && fail "$1: something on standard output"
	# every byte below 0x20 but tab and newline, and DEL, would reach the terminal raw
	if LC_ALL=C grep -q "$(printf '[\001-\010\013-\037\177]')" "$work/err"; then
		fail "$1: control bytes on standard error"
		LC_ALL=C grep -n "$(printf '[\001-\010\013-\037\177]')" "$work/err" | head -3 | od -c | head -5
	fi
}

# expect_binary FILE: a file that is not text stops at its first byte that is not: one
# error, which says so, and nothing after it.
expect_binary() {
	expect_garbage "$1"
	[ "$g_errors" -eq 1 ] || fail "$1: $g_errors errors, expected 1"
	expect_grep "$work/err" ': error: unexpected byte 0x[0-9a-f]{2} \(is this a scene file\?\); the rest of the file is not read$'
}

# keep_input FILE: copies a random input that failed next to the log, to reproduce it
keep_input() {
	[ "$fails" -eq 0 ] || cp "$1" "./hostile-$(basename "$1")" 2>/dev/null
}

head -c 1048576 /dev/urandom >"$work/urandom.scn"
expect_garbage "$work/urandom.scn"
keep_input "$work/urandom.scn"
expect_capped 1 10 "$SCN" check - <"$work/urandom.scn"
expect_grep "$work/err" '^<stdin>:[0-9]+:[0-9]+: error: '
gen "$work/random.scn" "
import random, sys
r = random.Random(7)
sys.stdout.buffer.write(bytes(r.getrandbits(8) for i in range(1 << 20)))"
expect_garbage "$work/random.scn"
# random text made of the language's own characters and words
gen "$work/tokens.scn" "
import random
r = random.Random(11)
words = ['{', '}', '(', ')', '<', '>', ',', '.', '..', '-', '+', '*', '/', '=', '1', '2.5', '1e3', 'x', 'pi',
         'sqrt', 'let', 'for', 'in', 'include', 'sphere', 'plane', 'material', 'mesh', 'camera', 'light',
         'diffuse', 'vertices', 'faces', '\"a.scn\"', '\"', '//', '/*', '*/', '\n', 'samples', 'max_depth']
print(' '.join(r.choice(words) for i in range(300000)))"
expect_garbage "$work/tokens.scn"

head -c 1048576 /dev/zero >"$work/nul.scn"
expect_binary "$work/nul.scn"
expect_grep "$work/err" '^.*nul.scn:1:1: error: unexpected byte 0x00 \(is this a scene file\?\); the rest of the file is not read$'

cp "$SCN" "$work/elf.scn"
expect_binary "$work/elf.scn"
expect_grep "$work/err" '^.*elf.scn:1:1: error: unexpected byte 0x7f'

gen "$work/png.scn" "
import struct, sys, zlib
def chunk(t, d):
    return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
raw = b''.join(b'\0' + bytes((x * 7 + y) % 256 for x in range(3 * 256)) for y in range(256))
sys.stdout.buffer.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', 256, 256, 8, 2, 0, 0, 0))
                        + chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))"
expect_binary "$work/png.scn"
expect_grep "$work/err" '^.*png.scn:1:1: error: unexpected byte 0x89'
if command -v gzip >/dev/null 2>&1; then
	gzip -c <"$SCN" >"$work/gz.scn"
	expect_binary "$work/gz.scn"
fi

# invalid UTF-8 outside strings and comments; inside comments it is allowed
printf 'let x = 1 \377\376 \303\050 \342\202 \360\050\214\050 \355\240\200 \300\257\n' >"$work/utf8.scn"
expect_binary "$work/utf8.scn"
expect_grep "$work/err" '^.*utf8.scn:1:11: error: unexpected byte 0xff'
printf '// \377\376 \303\050 \300\257\n/* \355\240\200 */ sphere { <0,0,0>, 1 }\n' >"$work/utf8_comment.scn"
expect_capped 0 5 "$SCN" check "$work/utf8_comment.scn"
gen "$work/utf8_many.scn" "import sys; sys.stdout.buffer.write(b'\xc3\x28\xff' * 500000)"
expect_binary "$work/utf8_many.scn"
# UTF-16 text
printf '\377\376s\000p\000h\000e\000r\000e\000 \000{\000 \000}\000\n\000' >"$work/utf16.scn"
expect_binary "$work/utf16.scn"

# terminal escapes in the source, in strings and in names of files
printf 'include "\033[2J\033]0;title\007"\nmesh { "\033[31mred.obj" }\n\033[1m sphere\n' >"$work/escape.scn"
expect_garbage "$work/escape.scn"
expect_grep "$work/err" "cannot read included file '\\?\\[2J\\?\\]0;title\\?'"

# carriage returns only, form feeds, vertical tabs
printf 'sphere { <0,0,0>, 1 }\rsphere { <0,0,0>, -1 }\r\f\v' >"$work/cr.scn"
expect_capped 1 5 "$SCN" check "$work/cr.scn"
expect_count "$work/err" ': error: ' 1
finish

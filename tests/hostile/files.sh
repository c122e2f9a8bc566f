# files.sh: what an include (or a mesh) may name: /dev/null, a directory, an endless
# device, a pipe, a binary file, itself, a chain 65 deep, a tree that doubles at every
# level. Every one ends in bounded time with a clear message.
. "$SCN_SRCDIR/tests/lib.sh"
. "$SCN_SRCDIR/tests/hostile/lib-hostile.sh"

# /dev/null is an empty file
printf 'include "/dev/null"\nsphere { <0,0,0>, 1 }\n' >"$work/null.scn"
expect_capped 0 5 "$SCN" check "$work/null.scn"
[ -s "$work/err" ] && fail "including /dev/null is not clean: $(cat "$work/err")"

# a directory
mkdir "$work/dir.scn"
printf 'include "dir.scn"\n' >"$work/incdir.scn"
expect_capped 1 5 "$SCN" check "$work/incdir.scn"
expect_grep "$work/err" "^.*incdir.scn:1:9: error: cannot read included file 'dir.scn': Is a directory$"
expect_count "$work/err" ': error: ' 1
printf 'mesh { "dir.scn" }\n' >"$work/meshdir.scn"
expect_capped 1 5 "$SCN" check "$work/meshdir.scn"
expect_grep "$work/err" "error: cannot read mesh file 'dir.scn': Is a directory$"

# endless devices stop at the 256 MiB limit on a scene's files
printf 'include "/dev/zero"\n' >"$work/zero.scn"
expect_capped 1 10 "$SCN" check "$work/zero.scn"
expect_grep "$work/err" "error: cannot read included file '/dev/zero': the scene's files exceed 256 MiB in all$"
expect_count "$work/err" ': error: ' 1
printf 'include "/dev/urandom"\n' >"$work/urandom.scn"
expect_capped 1 10 "$SCN" check "$work/urandom.scn"
expect_grep "$work/err" "error: cannot read included file '/dev/urandom': the scene's files exceed 256 MiB in all$"
expect_capped 3 10 "$SCN" check /dev/zero
expect_grep "$work/err" "^scn: error: cannot read '/dev/zero': larger than 256 MiB$"
expect_capped 3 10 "$SCN" check - </dev/zero
expect_grep "$work/err" "^scn: error: cannot read '<stdin>': larger than 256 MiB$"

# a pipe named by a scene could block forever: refused (a pipe on the command line is read)
if mkfifo "$work/fifo" 2>/dev/null; then
	printf 'include "fifo"\nmesh { "fifo" }\n' >"$work/incfifo.scn"
	expect_capped 1 5 "$SCN" check "$work/incfifo.scn"
	expect_grep "$work/err" "error: cannot read included file 'fifo': a pipe or a socket, not a file$"
	expect_grep "$work/err" "error: cannot read mesh file 'fifo': a pipe or a socket, not a file$"
	# standard input a pipe that stays open and empty
	printf 'include "/dev/stdin"\n' >"$work/incstdin.scn"
	exec 3<>"$work/fifo"
	expect_capped 1 5 "$SCN" check "$work/incstdin.scn" <&3
	exec 3>&-
	expect_grep "$work/err" "error: cannot read included file '/dev/stdin': a pipe or a socket, not a file$"
fi
printf 'sphere { <0,0,0>, 1 }\n' | capped 5 "$SCN" check /dev/stdin >"$work/out" 2>"$work/err" ||
	fail "a pipe on the command line is not read: $(cat "$work/err")"

# a binary file included: its errors, under "In file included from"
cp "$SCN" "$work/binary.scn"
printf 'sphere { <0,0,0>, 1 }\ninclude "binary.scn"\n' >"$work/incbinary.scn"
expect_capped 1 10 "$SCN" check "$work/incbinary.scn"
expect_grep "$work/err" '^In file included from .*incbinary.scn:2:9:$'
expect_grep "$work/err" '^.*binary.scn:1:1: error: unexpected byte 0x7f'
expect_small "$work/err" 100000

# cycles: itself, and through another file
printf 'include "self.scn"\n' >"$work/self.scn"
expect_capped 1 5 "$SCN" check "$work/self.scn"
expect_grep "$work/err" "error: include cycle: 'self.scn' is already being read$"
printf 'include "ping.scn"\n' >"$work/pong.scn"
printf 'include "pong.scn"\n' >"$work/ping.scn"
expect_capped 1 5 "$SCN" check "$work/ping.scn"
expect_grep "$work/err" "error: include cycle: 'ping.scn' is already being read$"

# a chain of 65 files: 64 levels of include are allowed
i=0
while [ $i -lt 70 ]; do
	printf 'include "chain%d.scn"\n' $((i + 1)) >"$work/chain$i.scn"
	i=$((i + 1))
done
printf 'sphere { <0,0,0>, 1 }\n' >"$work/chain64.scn"
expect_capped 0 5 "$SCN" check "$work/chain0.scn"
printf 'include "chain65.scn"\n' >"$work/chain64.scn"
expect_capped 1 5 "$SCN" check "$work/chain0.scn"
expect_grep "$work/err" "^.*chain64.scn:1:9: error: includes nested more than 64 deep$"
expect_count "$work/err" ': error: ' 1

# 30 files, each including the next twice: 2^30 includes, stopped at 10000 files
printf '\n' >"$work/tree30.scn"
i=0
while [ $i -lt 30 ]; do
	printf 'include "tree%d.scn"\ninclude "tree%d.scn"\n' $((i + 1)) $((i + 1)) >"$work/tree$i.scn"
	i=$((i + 1))
done
expect_capped 1 10 "$SCN" check "$work/tree0.scn"
expect_grep "$work/err" "error: more than 10000 files included in all \\(each include of a file counts\\)$"
expect_count "$work/err" ': error: ' 1
# the same with a 1 MB file at the bottom stops at 256 MiB
gen "$work/tree30.scn" "print('// ' + 'x' * 1000000)"
expect_capped 1 20 "$SCN" check "$work/tree0.scn"
expect_grep "$work/err" "error: cannot read included file 'tree30.scn': the scene's files exceed 256 MiB in all$"
# 10000 includes of a small file are allowed
printf 'sphere { <0,0,0>, 1 }\n' >"$work/small.scn"
gen "$work/many.scn" "print('include \"small.scn\"\n' * 10000)"
expect_capped 0 20 "$SCN" check "$work/many.scn"
finish

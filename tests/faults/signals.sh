# signals.sh: SIGINT and SIGTERM during a render, and during scn converge's POV-Ray run,
# end scn by that signal (status 128 + N) with no output, no temporary file and no
# temporary folder left, an existing output untouched and the child process gone; so
# does a crash (SIGSEGV) during a render.
. "$SCN_SRCDIR/tests/lib.sh"

cd "$work" || exit 99
command -v pgrep >/dev/null 2>&1 || { echo "SKIP: no pgrep"; exit 77; }

# a render of a few minutes: every kind of ray, many samples
cat >slow.scn <<'SCENE'
camera { location <0, 1.5, -6>  look_at <0, 1, 0>  resolution 1600, 1200 }
light  { position <-4, 8, -6> }
material glass { diffuse 0  specular 0.5  shininess 300  reflect 0.1  transmit 0.9  ior 1.5 }
plane  { <0, 1, 0>, 0  material { diffuse checker(<0.9, 0.9, 0.9>, <0.8, 0.1, 0.1>, 1) } }
sphere { <-1.2, 1, 1>, 1  material { diffuse 0.05  specular 0.8  reflect 0.9 } }
sphere { <1.2, 1, -0.5>, 1  material glass }
samples 256
SCENE

# wait_for CMD...: polls CMD every 0.05 s for up to 30 s (more under a sanitizer); false
# when it never succeeds
wait_for() {
	i=0
	while [ "$i" -lt 1200 ]; do
		"$@" && return 0
		sleep 0.05
		i=$((i + 1))
	done
	return 1
}

# has_temp DIR PID: PID's output file in DIR is open: a named temporary file there, or
# (outfile.c) one without a name, which only PID's descriptors show, as "DIR/#N (deleted)"
has_temp() {
	ls -a "$1" | grep -q '\.tmp$' && return 0
	for fd in /proc/"$2"/fd/*; do
		case $(readlink "$fd" 2>/dev/null) in "$(pwd -P)/$1/#"*) return 0 ;; esac
	done
	return 1
}

# stopped PID: waits for PID (up to 30 s, then kills it); its exit status in $status
stopped() {
	wait_for sh -c '! kill -0 "$1" 2>/dev/null || ps -o stat= -p "$1" | grep -q Z' sh "$1" ||
		{ fail "pid $1 still runs 30 s after the signal"; kill -KILL "$1"; }
	wait "$1"
	status=$?
}

# interrupt_render SIGNAL: a render into out/, stopped by SIGNAL once its temporary file
# exists; a file already at the output must survive
interrupt_render() {
	rm -rf out && mkdir out
	echo old >out/keep.png
	# a background job of a script ignores SIGINT: give the render the default action back
	env --default-signal="$1" "$SCN" render slow.scn -j 2 -q -o out/keep.png 2>"$work/err-$1" &
	pid=$!
	wait_for has_temp out "$pid" || fail "$1: no temporary file appeared in out/"
	kill -"$1" "$pid"
	stopped "$pid"
	want=$((128 + $(kill -l "$1")))
	[ "$status" -eq "$want" ] || fail "render stopped by SIG$1 exited $status, expected $want"
	[ "$(ls -A out)" = keep.png ] || fail "SIG$1 left in out/: $(ls -A out | tr '\n' ' ')"
	[ "$(cat out/keep.png)" = old ] || fail "SIG$1 changed the existing output"
	grep -qx "scn: stopped by SIG$1" "$work/err-$1" || { fail "SIG$1: no message"; cat "$work/err-$1"; }
}
interrupt_render INT
interrupt_render TERM

# a crash (SIGSEGV sent from outside stands in for one): the same removals, the default
# action's status, and a message that says scn crashed; a sanitizer build leaves crashes
# to the sanitizer, which reports them itself
if [ "$SCN_SANITIZED" != yes ]; then
	rm -rf out && mkdir out
	echo old >out/keep.png
	"$SCN" render slow.scn -j 2 -q -o out/keep.png 2>"$work/err-SEGV" &
	pid=$!
	wait_for has_temp out "$pid" || fail "SEGV: no temporary file appeared in out/"
	kill -SEGV "$pid"
	stopped "$pid"
	[ "$status" -eq $((128 + $(kill -l SEGV))) ] || fail "render crashed by SIGSEGV exited $status"
	[ "$(ls -A out)" = keep.png ] || fail "SIGSEGV left in out/: $(ls -A out | tr '\n' ' ')"
	[ "$(cat out/keep.png)" = old ] || fail "SIGSEGV changed the existing output"
	grep -qx "scn: crashed with SIGSEGV (a bug in scn); its temporary files are removed" "$work/err-SEGV" ||
		{ fail "SIGSEGV: no message"; cat "$work/err-SEGV"; }
fi

# scn converge with a POV-Ray that never ends (a stand-in on PATH): the signal kills and
# reaps it, and removes converge's temporary folder and the CSV's temporary file
mkdir bin
printf '#!/bin/sh\nexec sleep 300\n' >bin/povray
chmod +x bin/povray
cat >tiny.scn <<'SCENE'
camera { location <0, 1, -4>  look_at <0, 1, 0>  resolution 8, 6 }
light { position <-4, 8, -6> }
sphere { <0, 1, 0>, 1 }
SCENE
interrupt_converge() {
	rm -rf out tmp && mkdir out tmp
	PATH="$work/bin:$PATH" TMPDIR="$work/tmp" env --default-signal="$1" "$SCN" converge tiny.scn \
		--reference-samples 16 --budget 600 --csv out/t.csv -q >/dev/null 2>"$work/err-$1" &
	pid=$!
	wait_for pgrep -P "$pid" >/dev/null || fail "$1: converge started no POV-Ray"
	child=$(pgrep -P "$pid")
	[ -n "$(ls -A tmp)" ] || fail "$1: converge made no temporary folder in \$TMPDIR"
	kill -"$1" "$pid"
	stopped "$pid"
	want=$((128 + $(kill -l "$1")))
	[ "$status" -eq "$want" ] || fail "converge stopped by SIG$1 exited $status, expected $want"
	[ -z "$(ls -A tmp)" ] || fail "SIG$1 left in \$TMPDIR: $(ls -AR tmp | tr '\n' ' ')"
	[ -z "$(ls -A out)" ] || fail "SIG$1 left in out/: $(ls -A out | tr '\n' ' ')"
	if [ -n "$child" ] && kill -0 "$child" 2>/dev/null; then
		fail "SIG$1 left POV-Ray (pid $child) running"
		kill -KILL "$child"
	fi
}
interrupt_converge TERM
interrupt_converge INT
finish

# anim.sh: animation on the command line (LANGUAGE.md section 13): `scn render --frames`
# names its files as POV-Ray does or after a %d template, binds frame and clock in each
# frame exactly as --clock and literal numbers would, --cyclic; a failing frame is named,
# stops the run and leaves the frames before it; warnings come once; --progress and
# --stats per frame; `scn pov --clock`; the usage errors and POV-Ray's +K options.
. "$SCN_SRCDIR/tests/lib.sh"

cd "$work" || exit 99

# the sphere moves with clock and its colour follows frame: every frame differs
cat >anim.scn <<'EOF'
camera { location <0, 0, -5>  look_at <0, 0, 0>  resolution 32, 24 }
light  { position <0, 5, -5> }
sphere { <clock * 2 - 1, 0, 0>, 1  material { diffuse <frame / 10, 0.5, 0.5> } }
EOF

# files_are DIR WANT: the names in DIR, sorted, on one line
files_are() {
	got=$(cd "$1" && ls | LC_ALL=C sort | tr '\n' ' ' | sed 's/ $//')
	[ "$got" = "$2" ] || fail "$1 holds '$got', expected '$2'"
}

# last_line LINE: the last line on standard error is LINE
last_line() {
	[ "$(tail -n 1 "$work/err")" = "$1" ] || { fail "expected '$1' last"; sed 's/^/  | /' "$work/err"; }
}

# frames DIR ARGS...: renders anim.scn into the new folder DIR with ARGS, quietly
frames() {
	dir=$1
	shift
	mkdir "$dir"
	(cd "$dir" && exec "$SCN" render ../anim.scn -q "$@") >"$work/out" 2>"$work/err" ||
		{ fail "render --frames into $dir exited $?"; cat "$work/err"; }
}

# --- names: the number before the extension, padded to the width of B-1, or a template ---
frames n1 --frames 1..4
files_are n1 'anim1.png anim2.png anim3.png'
frames n2 --frames 1..12
files_are n2 'anim01.png anim02.png anim03.png anim04.png anim05.png anim06.png anim07.png anim08.png anim09.png anim10.png anim11.png'
frames n3 --frames 0..10 -o a.b.ppm
files_are n3 'a.b0.ppm a.b1.ppm a.b2.ppm a.b3.ppm a.b4.ppm a.b5.ppm a.b6.ppm a.b7.ppm a.b8.ppm a.b9.ppm'
frames n4 --frames 8..11 -o 'f%03d.png'
files_are n4 'f008.png f009.png f010.png'
frames n5 --frames 1..3 -o 'f%d-of-9.png'
files_are n5 'f1-of-9.png f2-of-9.png'
frames n6 --frames 1..3 -o '100%%.png'
files_are n6 '100%1.png 100%2.png'
# a dot in a folder's name is no extension
frames v1.0 --frames 1..3 -o ../v1.0/out.png
files_are v1.0 'out1.png out2.png'
# negative frames: a '-' before the padded digits; a template's %0Nd is printf's
frames n8 --frames -11..2
files_are n8 'anim-01.png anim-02.png anim-03.png anim-04.png anim-05.png anim-06.png anim-07.png anim-08.png anim-09.png anim-10.png anim-11.png anim00.png anim01.png'
frames n9 --frames -2..1 -o 'f%03d.png'
files_are n9 'f-01.png f-02.png f000.png'
no_temp "the frames"
# the "wrote" line names the frame and its clock
(cd n1 && "$SCN" render ../anim.scn --frames 1..4 --no-progress) 2>"$work/err" || fail "render --frames exited $?"
expect_grep "$work/err" '^scn: wrote anim2\.png \(frame 2, clock 0\.5\): 32 x 24, 1 sample per pixel, rendered in [0-9.]+ s$'
[ "$(grep -c '^scn: wrote' "$work/err")" -eq 3 ] || fail "three frames did not say 'wrote' three times"

# --- each frame is the scene evaluated with its frame and clock: the same bytes as the
# scene with the two numbers written in, and as --clock when only clock matters ---
# literal K C: anim.scn with frame K and clock C written in
literal() {
	sed -e "s/clock/($2)/" -e "s/frame/($1)/" anim.scn >literal.scn
}
frames bytes --frames 0..4 -o 'f%d.ppm'
k=0
for c in 0 0.33333333333333331 0.66666666666666663 1; do
	literal $k $c
	"$SCN" render literal.scn -q -o literal.ppm || fail "literal.scn exited $?"
	same_bytes bytes/f$k.ppm literal.ppm "frame $k of 0..4 against frame $k and clock $c written in"
	k=$((k + 1))
done
cmp -s bytes/f1.ppm bytes/f2.ppm && fail "frames 1 and 2 are the same image"
# --clock leaves frame 0
literal 0 0.25
"$SCN" render literal.scn -q -o literal.ppm
"$SCN" render anim.scn -q --clock 0.25 -o clock.ppm || fail "--clock 0.25 exited $?"
same_bytes literal.ppm clock.ppm "--clock 0.25 against frame 0 and clock 0.25 written in"
"$SCN" render anim.scn --clock 2.5e-1 -o clock.png 2>"$work/err"
expect_grep "$work/err" '^scn: wrote clock\.png \(clock 0\.25\): '

# a scene of clock alone: frame k and --clock with its clock (%.17g) give the same bytes
sed 's/frame \/ 10/0.3/' anim.scn >clock.scn
expect_status 0 "$SCN" render clock.scn -q --frames 3..10 -o 'c%d.ppm'
expect_status 0 "$SCN" render clock.scn -q --clock 0.16666666666666666 -o clock.ppm
same_bytes c4.ppm clock.ppm "frame 4 of 3..10 against --clock 1/6"
expect_status 0 "$SCN" render clock.scn -q --clock 1 -o clock.ppm
same_bytes c9.ppm clock.ppm "the last frame of 3..10 against --clock 1"
# --cyclic: clock (frame - A) / (B - A), never 1
expect_status 0 "$SCN" render clock.scn -q --frames 0..4 --cyclic -o 'y%d.ppm'
for k in 1 2 3; do
	expect_status 0 "$SCN" render clock.scn -q --clock "0.$((k * 25))" -o clock.ppm
	same_bytes y$k.ppm clock.ppm "--cyclic frame $k of 0..4 against --clock 0.$((k * 25))"
done
# a single frame has clock 0, cyclic or not
expect_status 0 "$SCN" render clock.scn -q --clock 0 -o clock.ppm
expect_status 0 "$SCN" render clock.scn -q --frames 7..8 -o 'one%d.ppm'
same_bytes one7.ppm clock.ppm "the single frame 7..8 against --clock 0"
expect_status 0 "$SCN" render clock.scn -q --frames 7..8 --cyclic -o 'cyc%d.ppm'
same_bytes cyc7.ppm clock.ppm "the single frame 7..8 --cyclic against --clock 0"

# --- a failing frame: named, it stops the run, the frames before it stay ---
cat >bad.scn <<'EOF'
camera { location <0, 0, -5>  look_at <0, 0, 0>  resolution 32, 24 }
light  { position <0, 5, -5> }
sphere { <0, 0, 0>, 3 - frame }
EOF
cp clock.ppm bad3.ppm
expect_status 1 "$SCN" render bad.scn -q --frames 1..6 -o 'bad%d.ppm'
expect_grep "$work/err" "^bad\.scn:3:21: error: a sphere's radius must be positive, not 0$"
last_line "scn: error: frame 3 (clock 0.5) failed; frames 1 and 2 were written"
[ -f bad1.ppm ] && [ -f bad2.ppm ] || fail "the frames before the failing one were not kept"
same_bytes clock.ppm bad3.ppm "the failing frame's older file"
[ -e bad4.ppm ] && fail "a frame after the failing one was written"
no_temp "a failing frame"
expect_status 1 "$SCN" render bad.scn -q --frames 3..6 -o 'bad%d.ppm'
last_line "scn: error: frame 3 (clock 0) failed; no frame was written"
expect_status 1 "$SCN" render bad.scn -q --frames 2..7 -o 'bad%d.ppm'
last_line "scn: error: frame 3 (clock 0.25) failed; frame 2 was written"
expect_status 1 "$SCN" render bad.scn -q --frames 0..4 -o 'bad%d.ppm'
last_line "scn: error: frame 3 (clock 1) failed; frames 0 to 2 were written"
expect_status 1 "$SCN" render bad.scn -q --frames 2..5 -o 'bad%d.ppm'
last_line "scn: error: frame 3 (clock 0.5) failed; frame 2 was written"
expect_status 1 "$SCN" render bad.scn -q --frames 2..9 -o 'bad%d.ppm'
last_line "scn: error: frame 3 (clock 0.16666666666666666) failed; frame 2 was written"
# an output that cannot be written: status 3, the frame named
expect_status 3 "$SCN" render anim.scn -q --frames 1..3 -o 'nodir/f%d.png'
expect_grep "$work/err" "^scn: cannot write 'nodir/f1\.png': No such file or directory$"
last_line "scn: error: frame 1 (clock 0) failed; no frame was written"

# --- warnings: the first frame's only; a later frame's diagnostics when it fails ---
printf 'material unused { diffuse 1 }\n' | cat bad.scn - >warn.scn
expect_status 0 "$SCN" render warn.scn -q --frames 0..3 -o 'w%d.ppm'
[ "$(grep -c "warning: material 'unused' is never used" "$work/err")" -eq 1 ] ||
	{ fail "the warning of three frames is not printed once"; sed 's/^/  | /' "$work/err"; }
expect_status 1 "$SCN" render warn.scn -q --frames 0..4 -o 'w%d.ppm'
[ "$(grep -c "warning: material 'unused' is never used" "$work/err")" -eq 2 ] ||
	{ fail "the failing frame's warning is not printed with its error"; sed 's/^/  | /' "$work/err"; }

# --- --progress counts frames; --stats per frame ---
expect_status 0 "$SCN" render anim.scn --frames 1..4 --progress -o 'p%d.png'
expect_grep "$work/err" '\[\.+\] 0/3 frames'
expect_grep "$work/err" '\[#+\.+\] 2/3 frames  ETA [0-9]+s'
expect_status 0 "$SCN" render anim.scn --frames 1..4 --progress -q -o 'p%d.png'
only_line "$work/err" ""
expect_status 0 "$SCN" render anim.scn --frames 1..4 --stats --no-progress -o 'p%d.png'
[ "$(grep -c '^time: parse' "$work/err")" -eq 3 ] || fail "--stats did not print each frame's times"
[ "$(grep -c '^rays: ' "$work/err")" -eq 3 ] || fail "--stats did not print each frame's rays"

# --- scn pov --clock: the scene at that moment, which the header names ---
expect_status 0 "$SCN" pov anim.scn --clock 0.25 -o -
expect_grep "$work/out" '^// anim\.pov: the POV-Ray 3\.7 equivalent of anim\.scn at clock 0\.25, written by scn '
expect_grep "$work/out" '^sphere \{ <-0\.5, 0, 0>, 1 '
expect_status 0 "$SCN" pov anim.scn -o -
grep -q 'at clock' "$work/out" && fail "scn pov without --clock names a clock"
expect_grep "$work/out" '^sphere \{ <-1, 0, 0>, 1 '

# --- standard input: --clock reads it once; --frames would read it for each frame ---
"$SCN" render - -q --clock 0.25 -o stdin.ppm <anim.scn || fail "render - --clock exited $?"
"$SCN" render anim.scn -q --clock 0.25 -o file.ppm
same_bytes file.ppm stdin.ppm "--clock 0.25 from standard input"

# --- bad command lines: status 2, the message, the usage, no file ---
mkdir usage
cd usage || exit 99
cp ../anim.scn .
usage_error "bad value 'x' for --clock (a finite number)" render anim.scn --clock x
usage_error "bad value 'inf' for --clock (a finite number)" render anim.scn --clock inf
usage_error "bad value 'nan' for --clock (a finite number)" render anim.scn --clock nan
usage_error "bad value '1e999' for --clock (a finite number)" render anim.scn --clock 1e999
usage_error "bad value ' 1' for --clock (a finite number)" render anim.scn --clock ' 1'
usage_error "bad value '0.5s' for --clock (a finite number)" pov anim.scn --clock 0.5s
usage_error "bad value '3' for --frames (A..B, whole numbers from -1000000000 to 1000000000)" render anim.scn --frames 3
usage_error "bad value '1..x' for --frames (A..B, whole numbers from -1000000000 to 1000000000)" render anim.scn --frames 1..x
usage_error "bad value '1.5..3' for --frames (A..B, whole numbers from -1000000000 to 1000000000)" render anim.scn --frames 1.5..3
usage_error "bad value '0..1000000001' for --frames (A..B, whole numbers from -1000000000 to 1000000000)" render anim.scn --frames 0..1000000001
usage_error "--frames 3..3 has no frames: A..B renders frames A to B-1" render anim.scn --frames 3..3
usage_error "--frames 4..1 has no frames: A..B renders frames A to B-1" render anim.scn --frames=4..1
usage_error "--clock and --frames do not go together: --frames sets each frame's clock" render anim.scn --clock 0 --frames 1..3
usage_error "--cyclic needs --frames" render anim.scn --cyclic
usage_error "--cyclic needs --frames" render anim.scn --cyclic --clock 0.5
usage_error "--frames reads the scene once for each frame: it cannot come from standard input" render - --frames 1..3
bad_template="a '%' must start %d or %0Nd (the frame number, N from 1 to 64) or %% (a '%')"
for out in 'a%x.png' 'a%5d.png' 'a%0d.png' 'a%065d.png' 'a%ld.png' 'a%.png' 'a%'; do
	usage_error "bad output name '$out' for frames: $bad_template" render anim.scn --frames 1..3 -o "$out"
done
usage_error "bad output name 'a%d-%02d.png' for frames: more than one %d or %0Nd" render anim.scn --frames 1..3 -o 'a%d-%02d.png'
usage_error "cannot tell the format of 'a1.bmp' (use .png, .exr or .ppm)" render anim.scn --frames 1..3 -o a.bmp
usage_error "cannot tell the format of 'a.p1ng' (use .png, .exr or .ppm)" render anim.scn --frames 1..3 -o 'a.p%dng'
# without --frames, OUT is a plain name
expect_status 0 "$SCN" render anim.scn -q -o 'plain%d.png'
[ -f 'plain%d.png' ] || fail "-o 'plain%d.png' without --frames did not write plain%d.png"
rm 'plain%d.png'
files_are . 'anim.scn'
# POV-Ray's animation options name scn's
usage_error "'+K0.5' looks like a POV-Ray option; scn render's equivalent is --clock 0.5" render anim.scn +K0.5
usage_error "'+KFI1' looks like a POV-Ray option; scn render's equivalent is --frames A..B (+KFI1 +KFF24 is --frames 1..25: B is one past the last frame)" render anim.scn +KFI1
usage_error "'+KC' looks like a POV-Ray option; scn render's equivalent is --cyclic" render anim.scn +KC
usage_error "'+K0.5' looks like a POV-Ray option; scn pov's equivalent is --clock 0.5" pov anim.scn +K0.5
finish

# converge.sh: `scn converge` (LANGUAGE.md section 8) on a small scene at 32 x 24: the
# table's rows and columns, error falling as jittered samples rise, the CSV and the SVG
# plot well formed, the budget, a reference file, exit statuses; and, when povray is
# installed, one quick run with the POV-Ray series and the equal-error line, and one of a
# soft-shadow scene with a series per area_light adaptive level.
. "$SCN_SRCDIR/tests/lib.sh"

cd "$work" || exit 99
mkdir tmp && TMPDIR=$work/tmp && export TMPDIR

cat >tiny.scn <<'EOF'
camera { location <0, 1.5, -6>  look_at <0, 1, 0>  fov 55  resolution 64, 48 }
light  { position <-4, 8, -6>  color <1, 1, 1> }
skybox { zenith <0.15, 0.35, 0.8>  horizon <0.75, 0.85, 1> }
material mirror { diffuse 0.05  specular 0.8  shininess 200  reflect 0.9 }
material floor  { diffuse checker(<0.9, 0.9, 0.9>, <0.8, 0.1, 0.1>, 1) }
plane  { <0, 1, 0>, 0  material floor }
sphere { <-1.2, 1, 1>, 1  material mirror }
sphere { <1.2, 0.8, -0.5>, 0.8  material { diffuse <0.2, 0.5, 0.9> } }
EOF

num='[0-9.]+(e-?[0-9]+)?'

# --- without POV-Ray: every scn series up to count 16 (a 256-sample reference) ---
expect_status 0 "$SCN" converge tiny.scn -W 32 --no-pov --reference-samples 256 --budget 60 -j 2 \
	--csv t.csv --plot t.svg
cp "$work/out" table.txt
expect_grep table.txt '^scene: tiny\.scn, 32 x 24, max_depth 5, 2 threads$'
expect_grep table.txt '^reference: scn grid 16 x 16 = 256 samples per pixel, rendered in [0-9.]+ s$'
expect_grep table.txt '^series +setting +spp +seconds +RMSE +est\. RMSE$'
for pattern in random jittered poisson grid; do
	for count in 1 4 16; do
		est=$num
		[ "$pattern" = grid ] && est=-
		expect_grep table.txt "^scn $pattern +count $count +$count +[0-9]+\.[0-9]{3} +$num +$est\$"
	done
	grep -q "^scn $pattern  *count 64 " table.txt && fail "scn $pattern went past a 16th of the reference's count"
done
expect_grep table.txt "^scn adaptive +target 0\.02 max 16 +$num +[0-9]+\.[0-9]{3} +$num +$num\$"
# the adaptive cap follows the target (four times the samples for half the target) up to the
# reference's count, and the samples taken rise with it
expect_grep table.txt "^scn adaptive +target 0\.01 max 64 "
expect_grep table.txt "^scn adaptive +target 0\.005 max 256 "
expect_grep table.txt "^scn adaptive +target 0\.0025 max 256 "
grep -q '^POV-Ray ' table.txt && fail "--no-pov ran POV-Ray"
[ "$(tail -n 1 table.txt)" = "at equal error: no POV-Ray series to compare with (--no-pov)" ] ||
	fail "the last line is '$(tail -n 1 table.txt)'"
[ -s "$work/err" ] || fail "no progress lines on standard error"

# the CSV: the header, six fields on every line, one line per row of the table
[ "$(head -n 1 t.csv)" = "series,setting,samples_per_pixel,seconds,rmse,estimated_rmse" ] ||
	fail "the CSV's header is '$(head -n 1 t.csv)'"
awk -F, 'NF != 6 { bad = 1 } END { exit bad }' t.csv || fail "a CSV line does not have 6 fields"
rows=$(grep -cE '^scn [a-z]+ ' table.txt)
[ "$(($(wc -l <t.csv) - 1))" -eq "$rows" ] || fail "the CSV has $(($(wc -l <t.csv) - 1)) rows, the table $rows"
# the error falls as the jittered samples rise
awk -F, '$1 == "scn jittered" { if (n++ && $5 >= last) bad = 1; last = $5 } END { exit bad || n < 3 }' t.csv ||
	{ fail "the jittered RMSE does not fall with the count"; grep jittered t.csv; }
awk -F, '$1 == "scn adaptive" { if (n++ && ($3 <= spp || $6 >= est)) bad = 1; spp = $3; est = $6 }
	END { exit bad || n < 4 }' t.csv ||
	{ fail "the adaptive series' samples do not rise, or its estimated error fall, as the target falls"; grep adaptive t.csv; }
# the renders of the random patterns estimate their error (not 0), grid's do not
awk -F, 'NR > 1 && ($1 == "scn grid" ? $6 != "" : !($6 > 0)) { bad = 1 } END { exit bad }' t.csv ||
	{ fail "an estimated RMSE is missing or 0, or grid has one"; cat t.csv; }

# the SVG: well-formed XML, one line per series and the legend's
if command -v python3 >/dev/null 2>&1; then
	python3 -c 'import xml.dom.minidom,sys; xml.dom.minidom.parse(sys.argv[1])' t.svg ||
		fail "t.svg is not well-formed XML"
fi
expect_grep t.svg '^<svg xmlns="http://www.w3.org/2000/svg"'
[ "$(grep -c '^<polyline ' t.svg)" -eq 5 ] || fail "t.svg has $(grep -c '^<polyline ' t.svg) polylines, not 5"
expect_grep t.svg '>scn jittered</text>'
expect_grep t.svg '>RMSE against the reference'
ls -a | grep -q '\.tmp$' && fail "temporary files left: $(ls -a | grep '\.tmp$')"

# --- a tiny budget: the two timing renders and the reference only, the rest named as not run ---
expect_status 0 "$SCN" converge tiny.scn -W 32 -H 24 --no-pov --reference-samples 64 --budget 0.0001 -q
expect_grep "$work/out" '^scn grid +count 1 +1 '
expect_grep "$work/out" '^scn grid +count 4 +4 '
expect_grep "$work/out" '^not run, over the budget of 0\.0001 s: .*scn jittered count 1'
[ "$(grep -cE '^scn [a-z]+ ' "$work/out")" -eq 2 ] || fail "the tiny budget ran more than the timing renders"
[ -s "$work/err" ] && fail "-q printed: $(cat "$work/err")"

# --- a reference file: its size is the renders' size ---
"$SCN" render tiny.scn -W 40 -H 30 -s 64 -p grid -o ref.exr --float -q || fail "scn render ref.exr exited $?"
expect_status 0 "$SCN" converge tiny.scn --reference ref.exr --no-pov --budget 2 -q
expect_grep "$work/out" '^scene: tiny\.scn, 40 x 30,'
expect_grep "$work/out" '^reference: ref\.exr$'

# --- statuses ---
expect_status 2 "$SCN" converge
expect_grep "$work/err" 'no scene given'
expect_status 2 "$SCN" converge tiny.scn --bogus
expect_grep "$work/err" "unknown option '--bogus' for converge"
expect_status 2 "$SCN" converge tiny.scn --budget
expect_status 2 "$SCN" converge tiny.scn --budget 0
expect_status 2 "$SCN" converge tiny.scn --budget ten
expect_status 2 "$SCN" converge tiny.scn -j -1
expect_status 2 "$SCN" converge tiny.scn -W 0
expect_status 2 "$SCN" converge tiny.scn --reference-samples 20
expect_grep "$work/err" 'square count'
expect_status 2 "$SCN" converge tiny.scn --plot out.png
expect_grep "$work/err" 'name the file \.svg'
expect_status 2 "$SCN" converge tiny.scn tiny.scn
expect_status 2 "$SCN" converge tiny.scn --reference ref.exr -W 32 --no-pov
expect_grep "$work/err" 'the reference ref\.exr is 40 x 30, but the renders would be 32 x 24'
expect_status 3 "$SCN" converge missing.scn
expect_status 3 "$SCN" converge tiny.scn --reference missing.png
expect_status 3 "$SCN" converge tiny.scn --csv no/such/dir/t.csv
printf 'sphere { <0,0,0>, -1 }\n' >bad.scn
expect_status 1 "$SCN" converge bad.scn --no-pov
expect_status 0 "$SCN" help converge
expect_grep "$work/out" '^usage: scn converge SCENE'

# --- POV-Ray, when installed: its series and the equal-error line ---
if ! command -v povray >/dev/null 2>&1; then
	echo "povray not found: skipping the POV-Ray series"
	finish
fi
HOME=$work && export HOME
expect_status 0 "$SCN" converge tiny.scn -W 32 --reference-samples 256 --budget 15 -j 2 --csv p.csv
cp "$work/out" pov.txt
expect_grep pov.txt "^POV-Ray +-A +1 +[0-9]+\.[0-9]{3} +$num +-\$"
expect_grep pov.txt "^POV-Ray +\+A0\.0 \+AM2 \+R1 -J +4 +[0-9]+\.[0-9]{3} +$num +-\$"
expect_grep p.csv '^POV-Ray,-A,1,'
# POV-Ray's -A and scn's one centred sample are the same image (but for 16-bit rounding)
awk -F, '$2 == "-A" || ($1 == "scn grid" && $3 == 1) { r[n++] = $5 }
	END { d = r[0] - r[1]; exit !(n == 2 && d * d < 1e-4 * r[0] * r[0]) }' p.csv ||
	{ fail "POV-Ray -A and scn grid count 1 differ in RMSE"; cat p.csv; }
tail -n 1 pov.txt | grep -Eq "^at equal error \(RMSE $num\), scn takes $num s and POV-Ray $num s: scn/POV-Ray = $num \(scn [a-z]+\)\$" ||
	fail "the last line is '$(tail -n 1 pov.txt)'"
[ -z "$(ls tmp)" ] || fail "the POV-Ray folder was left: $(ls tmp)"

# --- soft shadows: one more POV-Ray series per area_light adaptive level below the full
# subdivision (a 5 x 5 light: levels 0 and 1), each in the table, the CSV and the plot, and
# the last line names the fastest ---
cat >soft.scn <<'EOF'
camera { location <0, 3, -7>  look_at <0, 0.8, 0>  fov 50  resolution 64, 48 }
light  { position <-3, 6, -3>  area { <2, 0, 0>, <0, 0, 2>, 5, 5  jitter } }
plane  { <0, 1, 0>, 0  material { diffuse <0.8, 0.8, 0.8> } }
sphere { <-1, 1, 0>, 1  material { diffuse <0.9, 0.3, 0.2> } }
EOF
expect_status 0 "$SCN" converge soft.scn -W 16 --reference-samples 16 --budget 20 -j 2 --csv s.csv --plot s.svg -q
cp "$work/out" soft.txt
for series in 'POV-Ray' 'POV-Ray adaptive 0' 'POV-Ray adaptive 1'; do
	expect_grep soft.txt "^$series +-A +1 +[0-9]+\.[0-9]{3} +$num +-\$"
	expect_grep s.csv "^$series,-A,1,"
	expect_grep s.svg ">$series</text>"
done
grep -q '^POV-Ray adaptive 2 ' soft.txt && fail "a POV-Ray series at adaptive 2, which is a 5 x 5 light's full subdivision"
[ "$(grep -c '^<polyline ' s.svg)" -eq 8 ] || fail "s.svg has $(grep -c '^<polyline ' s.svg) polylines, not 8"
tail -n 1 soft.txt | grep -Eq "^at equal error \(RMSE $num\), scn takes $num s and POV-Ray $num s: scn/POV-Ray = $num \(scn [a-z]+; POV-Ray's fastest there: POV-Ray( adaptive [01])?\)\$" ||
	fail "the last line is '$(tail -n 1 soft.txt)'"
[ -z "$(ls tmp)" ] || fail "the POV-Ray folder was left: $(ls tmp)"
finish

# equal_rays.sh: bench/ compares scn with POV-Ray at equal camera rays a pixel: the
# povray command bench.py runs for a scene of 5 jittered samples a pixel traces, by
# POV-Ray's own statistics (Pixels + Samples), as many camera rays as scn's --stats
# counts, within the extra row POV-Ray traces (5.1 at 40 x 30). Skipped without POV-Ray.
. "$SCN_SRCDIR/tests/lib.sh"
command -v povray >/dev/null 2>&1 || { echo "SKIP: povray is not installed"; exit 77; }
command -v python3 >/dev/null 2>&1 || { echo "SKIP: python3 is not installed"; exit 77; }
cd "$work" || exit 99

cat >five.scn <<'SCENE'
camera { location <0, 1, -4>  look_at <0, 0.5, 0>  resolution 40, 30 }
light  { position <-3, 5, -4> }
samples 5
plane  { <0, 1, 0>, 0 }
sphere { <0, 0.6, 0>, 0.6  material { diffuse <0.9, 0.3, 0.2> } }
SCENE
expect_status 0 "$SCN" render five.scn -o five-scn.png --stats -q
scn_rays=$(sed -n 's/^rays: *camera \([0-9]*\) .*/\1/p' "$work/err")
[ "$scn_rays" = 6000 ] || fail "scn traced $scn_rays camera rays, expected 5 x 1200"
expect_status 0 "$SCN" pov five.scn -o five.pov
HOME=$work SCN_BENCH=$SCN_SRCDIR/bench python3 - five.pov >rays.txt 2>&1 <<'PY' || { fail "bench.py's command failed"; cat rays.txt; }
import os, subprocess, sys
sys.path.insert(0, os.environ["SCN_BENCH"])
sys.dont_write_bytecode = True
import bench
cmd = bench.pov_command(sys.argv[1], "5")
p = subprocess.run(cmd, capture_output=True, text=True)
print(" ".join(cmd))
print(bench.pov_camera_rays(p.stderr))
PY
pov_rays=$(tail -n 1 rays.txt)
awk -v p="$pov_rays" 'BEGIN { r = p / 1200; exit !(r >= 5 && r <= 5.1) }' ||
	{ fail "POV-Ray traced $pov_rays camera rays for 1200 pixels, scn 6000"; cat rays.txt; }
finish

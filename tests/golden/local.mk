# tests/golden/local.mk: renders that must equal committed images bit for bit (golden.sh).
TESTS += tests/golden/golden.sh
EXTRA_DIST += tests/golden/golden.sh tests/golden/noise.scn tests/golden/noise.png

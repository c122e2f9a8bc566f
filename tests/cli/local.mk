# tests/cli/local.mk: the tests of this folder (see tests/run-test).
TESTS += tests/cli/commands.sh
EXTRA_DIST += tests/cli/commands.sh
TESTS += tests/cli/render.sh
EXTRA_DIST += tests/cli/render.sh
TESTS += tests/cli/diff.sh
EXTRA_DIST += tests/cli/diff.sh
TESTS += tests/cli/pov.sh
EXTRA_DIST += tests/cli/pov.sh
TESTS += tests/cli/estimate.sh
EXTRA_DIST += tests/cli/estimate.sh
TESTS += tests/cli/converge.sh
EXTRA_DIST += tests/cli/converge.sh
TESTS += tests/cli/options.sh
EXTRA_DIST += tests/cli/options.sh
TESTS += tests/cli/anim.sh
EXTRA_DIST += tests/cli/anim.sh

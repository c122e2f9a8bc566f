# tests/cli/local.mk: the tests of this folder (see tests/run-test).
TESTS += tests/cli/commands.sh
EXTRA_DIST += tests/cli/commands.sh

# tests/mesh/local.mk: the tests of this folder: mesh files as scn reads them.
TESTS += tests/mesh/messages.sh
EXTRA_DIST += tests/mesh/messages.sh
TESTS += tests/mesh/testmodels.sh
EXTRA_DIST += tests/mesh/testmodels.sh tests/mesh/formats.txt

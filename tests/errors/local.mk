# tests/errors/local.mk: the tests of this folder (see tests/run-test).
TESTS += tests/errors/unknown_material.scn
EXTRA_DIST += tests/errors/unknown_material.scn tests/errors/unknown_material.err

# tests/parse/local.mk: the tests of this folder (see tests/run-test).

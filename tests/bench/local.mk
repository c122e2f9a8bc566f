# tests/bench/local.mk: the tests of bench/'s own arithmetic (its timings are not tested).
TESTS += tests/bench/equal_rays.sh
EXTRA_DIST += tests/bench/equal_rays.sh

# tests/layout/local.mk: the sources' layering, read from the includes and from the
# libraries' symbols (check.sh): no cycle, and no reference up the tree but the argued one.
TESTS += tests/layout/check.sh
EXTRA_DIST += tests/layout/check.sh

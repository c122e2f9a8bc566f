# examples/local.mk: the example scenes; each must check clean (no errors, no warnings).
EXAMPLES = examples/whitted.scn
TESTS += $(EXAMPLES)
EXTRA_DIST += $(EXAMPLES)

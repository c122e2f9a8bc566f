# tests/faults/local.mk: faults around a run: signals, unwritable outputs, requests too big
# for the machine, running out of memory.
FAULT_TESTS = \
	tests/faults/signals.sh \
	tests/faults/output.sh \
	tests/faults/memory.sh \
	tests/faults/alloc_sweep.sh
TESTS += $(FAULT_TESTS)
EXTRA_DIST += $(FAULT_TESTS)

# tests/local.mk: `make check`. A .scn test is checked by tests/run-test according to its
# folder; a .sh test is a script that runs $SCN itself. Each folder lists its own files.
TEST_EXTENSIONS = .scn .sh
SCN_LOG_COMPILER = $(SHELL) $(srcdir)/tests/run-test
SH_LOG_COMPILER = $(SHELL)
AM_TESTS_ENVIRONMENT = SCN='$(abs_builddir)/scn'; export SCN; \
	SCN_SRCDIR='$(abs_srcdir)'; export SCN_SRCDIR; \
	SCN_SANITIZED='$(SCN_SANITIZED)'; export SCN_SANITIZED; \
	PROBE='$(abs_builddir)/tests/render/probe'; export PROBE; \
	LSAN_OPTIONS="suppressions=$(abs_srcdir)/tests/lsan.supp:print_suppressions=0$${LSAN_OPTIONS:+:$$LSAN_OPTIONS}"; \
	export LSAN_OPTIONS;
EXTRA_DIST += tests/run-test tests/lib.sh tests/lsan.supp

include tests/errors/local.mk
include tests/parse/local.mk
include tests/cli/local.mk
include tests/golden/local.mk
include tests/hostile/local.mk
EXTRA_DIST += tests/unit/check.h tests/unit/random.h
include tests/unit/local.mk
include tests/render/local.mk
include tests/pov/local.mk
include tests/faults/local.mk
include tests/valgrind/local.mk
include tests/extreme/local.mk
include tests/fuzz/local.mk
include tests/layout/local.mk
include tests/bench/local.mk
include tests/editors/local.mk
include tests/mesh/local.mk
include tests/pairs/local.mk
include tests/cpu/local.mk

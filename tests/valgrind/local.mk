# tests/valgrind/local.mk: `make check-valgrind`, a subset of scn's work under valgrind's
# memcheck (not part of `make check`: it takes a few minutes); .ci/run runs it.
check-valgrind: scn$(EXEEXT)
	SCN='$(abs_builddir)/scn$(EXEEXT)' SCN_SRCDIR='$(abs_srcdir)' $(SHELL) $(srcdir)/tests/valgrind/run.sh
.PHONY: check-valgrind
EXTRA_DIST += tests/valgrind/run.sh

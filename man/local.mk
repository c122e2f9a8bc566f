# man/local.mk: the manual page, and a test that keeps its example equal to
# examples/manpage.scn (which examples/local.mk checks like every example).
dist_man_MANS += man/scn.1
TESTS += man/example.sh
EXTRA_DIST += man/example.sh

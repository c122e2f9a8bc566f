# tests/editors/local.mk: the editor and shell files of editors/: each loads in its program
# and knows the options of scn.
TESTS += tests/editors/bash.sh
EXTRA_DIST += tests/editors/bash.sh

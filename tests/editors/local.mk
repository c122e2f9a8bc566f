# tests/editors/local.mk: the editor and shell files of editors/: each loads in its program
# (bash, Vim, a TextMate tokenizer) and knows the words of lang/ and the options of scn, and
# `make install` puts them where configure said (install.sh, which gets configure's folders
# here, and knows what editors/local.mk should put in them).
TESTS += tests/editors/bash.sh tests/editors/vim.sh tests/editors/textmate.sh tests/editors/install.sh
EXTRA_DIST += tests/editors/bash.sh tests/editors/vim.sh tests/editors/textmate.sh tests/editors/install.sh
EXTRA_DIST += tests/editors/lib.sh tests/editors/groups.vim tests/editors/textmate.py
EXTRA_DIST += tests/editors/sample.scn tests/editors/sample.codes
AM_TESTS_ENVIRONMENT += SCN_BUILDDIR='$(abs_builddir)'; export SCN_BUILDDIR; \
	SCN_INSTALL_DIRS='$(BASH_COMPLETION_DIR) $(vimfilesdir) $(pkgdatadir)'; \
	export SCN_INSTALL_DIRS;

# tests/editors/local.mk: the editor and shell files of editors/: each loads in its program
# (bash, Vim, a TextMate tokenizer) and knows the words of lang/ and the options of scn.
TESTS += tests/editors/bash.sh tests/editors/vim.sh tests/editors/textmate.sh
EXTRA_DIST += tests/editors/bash.sh tests/editors/vim.sh tests/editors/textmate.sh
EXTRA_DIST += tests/editors/lib.sh tests/editors/groups.vim tests/editors/textmate.py
EXTRA_DIST += tests/editors/sample.scn tests/editors/sample.codes

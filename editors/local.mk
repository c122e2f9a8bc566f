# editors/local.mk: the editor and shell files, installed where their programs look: the
# bash completion in bash-completion's folder (configure: --with-bash-completion-dir), Vim's
# syntax and filetype files in a vimfiles folder (--with-vimfilesdir), the TextMate grammar
# under the package's data folder, for an editor's settings to name.
bashcompletiondir = $(BASH_COMPLETION_DIR)
dist_bashcompletion_DATA = editors/bash/scn
vimsyntaxdir = $(vimfilesdir)/syntax
dist_vimsyntax_DATA = editors/vim/syntax/scn.vim
vimftdetectdir = $(vimfilesdir)/ftdetect
dist_vimftdetect_DATA = editors/vim/ftdetect/scn.vim
textmatedir = $(pkgdatadir)/textmate
dist_textmate_DATA = editors/textmate/scn.tmLanguage.json
# bash-completion's folder is outside the prefix (/usr/share/...): distcheck installs as
# a user into a prefix of its own, so it names a folder in that prefix
AM_DISTCHECK_CONFIGURE_FLAGS = --with-bash-completion-dir='$${prefix}/share/bash-completion/completions'

# editors/local.mk: the editor and shell files, installed where their programs look: the
# bash completion in bash-completion's folder (configure: --with-bash-completion-dir).
bashcompletiondir = $(BASH_COMPLETION_DIR)
dist_bashcompletion_DATA = editors/bash/scn
# bash-completion's folder is outside the prefix (/usr/share/...): distcheck installs as
# a user into a prefix of its own, so it names a folder in that prefix
AM_DISTCHECK_CONFIGURE_FLAGS = --with-bash-completion-dir='$${prefix}/share/bash-completion/completions'

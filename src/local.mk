# src/local.mk: the scn command.
bin_PROGRAMS += scn
scn_SOURCES = %D%/main.c
scn_LDADD = lang/libscnlang.a

# src/local.mk: the scn command.
bin_PROGRAMS += scn
scn_SOURCES = %D%/main.c %D%/cli.c %D%/cli.h %D%/anim.c %D%/anim.h %D%/pov_hint.c %D%/pov_hint.h %D%/cmd_check.c %D%/cmd_render.c
scn_LDADD = $(SCN_LIBS)
scn_SOURCES += src/cmd_diff.c
scn_SOURCES += %D%/cmd_pov.c
scn_SOURCES += %D%/cmd_converge.c %D%/plot.c %D%/plot.h %D%/povray.c %D%/povray.h
scn_SOURCES += %D%/mesh_dump.c %D%/mesh_dump.h
scn_SOURCES += %D%/tile.c %D%/tile.h %D%/tile_part.c %D%/tile_part.h %D%/cmd_merge.c
# tile.c hashes with xxHash
scn_CPPFLAGS = $(AM_CPPFLAGS) $(XXHASH_CFLAGS)

# src/local.mk: the scn command.
bin_PROGRAMS += scn
scn_SOURCES = %D%/main.c %D%/cli.c %D%/cli.h %D%/anim.c %D%/anim.h %D%/pov_hint.c %D%/pov_hint.h %D%/cmd_check.c %D%/cmd_render.c
scn_SOURCES += src/cmd_diff.c
scn_SOURCES += %D%/cmd_pov.c
scn_SOURCES += %D%/cmd_converge.c %D%/plot.c %D%/plot.h %D%/povray.c %D%/povray.h
scn_SOURCES += %D%/mesh_dump.c %D%/mesh_dump.h
scn_SOURCES += %D%/tile.c %D%/tile.h %D%/tile_part.c %D%/tile_part.h %D%/cmd_merge.c
scn_LDADD = render/dist/libscndist_none.a render/dist/libscndist.a $(SCN_LIBS)
# scn-mpi: scn with MPI, which scn becomes under an MPI launcher (render/dist/dist.h)
if HAVE_MPI
pkglibexec_PROGRAMS += scn-mpi
scn_mpi_SOURCES = $(scn_SOURCES)
scn_mpi_LDADD = render/dist/libscndist_mpi.a render/dist/libscndist.a $(SCN_LIBS) $(MPI_LIBS)
endif

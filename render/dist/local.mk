# render/dist/local.mk: scn render over the processes of an MPI launcher (dist.h). scn
# links dist_none.c, which has no MPI; scn-mpi links dist_mpi.c and MPI. What both share
# is a library of its own.
DIST_INCLUDES = -I$(srcdir)/%D% $(RENDER_INCLUDES)
noinst_LIBRARIES += render/dist/libscndist.a render/dist/libscndist_none.a
render_dist_libscndist_a_CPPFLAGS = $(BASE_CPPFLAGS) $(DIST_INCLUDES)
render_dist_libscndist_a_SOURCES = %D%/dist.h %D%/launch.c %D%/launch.h %D%/frame.c
render_dist_libscndist_none_a_CPPFLAGS = $(BASE_CPPFLAGS) $(DIST_INCLUDES) -DPKGLIBEXECDIR='"$(pkglibexecdir)"'
render_dist_libscndist_none_a_SOURCES = %D%/dist_none.c
if HAVE_MPI
noinst_LIBRARIES += render/dist/libscndist_mpi.a
render_dist_libscndist_mpi_a_CPPFLAGS = $(BASE_CPPFLAGS) $(DIST_INCLUDES) $(MPI_CFLAGS)
render_dist_libscndist_mpi_a_SOURCES = %D%/dist_mpi.c
endif

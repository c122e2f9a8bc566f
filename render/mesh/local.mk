# render/mesh/local.mk: mesh files read through assimp, checked and joined.
noinst_LIBRARIES += render/mesh/libscnmesh.a
render_mesh_libscnmesh_a_CPPFLAGS = $(AM_CPPFLAGS) $(ASSIMP_CFLAGS)
render_mesh_libscnmesh_a_CFLAGS = $(AM_CFLAGS) $(AVX_CFLAGS)
render_mesh_libscnmesh_a_SOURCES = %D%/mesh_import.c %D%/mesh_import.h %D%/mesh_join.c %D%/mesh_join.h \
	%D%/mesh_header.c %D%/mesh_header.h

# render/mesh/local.mk: mesh files read through assimp, checked and joined, and their materials.
noinst_LIBRARIES += render/mesh/libscnmesh.a
MESH_INCLUDES = -I$(srcdir)/%D% $(UTIL_INCLUDES)
render_mesh_libscnmesh_a_CPPFLAGS = $(BASE_CPPFLAGS) $(MESH_INCLUDES) $(ASSIMP_CFLAGS)
render_mesh_libscnmesh_a_CFLAGS = $(AM_CFLAGS) $(AVX_CFLAGS)
render_mesh_libscnmesh_a_SOURCES = %D%/mesh_import.c %D%/mesh_import.h %D%/mesh_join.c %D%/mesh_join.h \
	%D%/mesh_material.c %D%/mesh_material.h \
	%D%/mesh_header.c %D%/mesh_header.h

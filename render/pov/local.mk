# render/pov/local.mk: the POV-Ray export of a lowered scene.
POV_INCLUDES = -I$(srcdir)/%D% $(RENDER_INCLUDES)
noinst_LIBRARIES += render/pov/libscnpov.a
render_pov_libscnpov_a_CPPFLAGS = $(BASE_CPPFLAGS) $(POV_INCLUDES)
render_pov_libscnpov_a_CFLAGS = $(AM_CFLAGS) $(AVX_CFLAGS)
render_pov_libscnpov_a_SOURCES = %D%/pov_export.c %D%/pov_export.h %D%/pov_material.c %D%/pov_material.h \
	%D%/pov_mesh.c %D%/pov_mesh.h %D%/pov_solid.c %D%/pov_solid.h %D%/pov_texture.c %D%/pov_texture.h \
	%D%/pov_write.c %D%/pov_write.h
# pov_docdir.h: the folder `make install` puts doc/povray.md in, which every .pov's header
# names. make writes it, as only make knows $(docdir) in full.
nodist_render_pov_libscnpov_a_SOURCES = pov_docdir.h
BUILT_SOURCES += pov_docdir.h
CLEANFILES += pov_docdir.h
pov_docdir.h: Makefile
	$(AM_V_GEN)echo '#define POV_DOCDIR "$(docdir)"' >$@-t && mv $@-t $@

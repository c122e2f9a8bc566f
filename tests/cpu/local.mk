# tests/cpu/local.mk: the portable code path. scn_portable is scn with the renderer's
# libraries compiled again without AVX_CFLAGS, as for a CPU without AVX (the front end,
# lang/, never gets them and is linked as it is); portable.sh checks that it writes the
# bytes scn writes.
check_PROGRAMS += tests/cpu/scn_portable
tests_cpu_scn_portable_SOURCES = $(scn_SOURCES) $(render_pov_libscnpov_a_SOURCES) \
	$(render_libscnlower_a_SOURCES) $(render_libscnrender_a_SOURCES) $(render_accel_libscnaccel_a_SOURCES) \
	$(render_shape_libscnshape_a_SOURCES) $(render_texture_libscntexture_a_SOURCES) \
	$(render_mesh_libscnmesh_a_SOURCES) $(render_image_libscnimage_a_SOURCES)
tests_cpu_scn_portable_CPPFLAGS = $(AM_CPPFLAGS) $(PNG_CFLAGS) $(EXR_CFLAGS) $(ASSIMP_CFLAGS)
tests_cpu_scn_portable_CFLAGS = $(AM_CFLAGS)
tests_cpu_scn_portable_LDADD = render/dist/libscndist_none.a render/dist/libscndist.a lang/libscnlang.a lang/util/libscnutil.a $(PNG_LIBS) $(EXR_LIBS) $(ASSIMP_LIBS) \
	$(XXHASH_LIBS) -lm
TESTS += tests/cpu/portable.sh
EXTRA_DIST += tests/cpu/portable.sh

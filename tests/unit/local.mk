# tests/unit/local.mk: C unit tests of the renderer's parts; each is a program that
# exits 0 when every assertion holds (see tests/unit/check.h). Add one as:
#   check_PROGRAMS += tests/unit/test_NAME
#   TESTS += tests/unit/test_NAME
#   tests_unit_test_NAME_SOURCES = tests/unit/test_NAME.c
#   tests_unit_test_NAME_LDADD = $(SCN_LIBS)
check_PROGRAMS += tests/unit/test_mesh_import
TESTS += tests/unit/test_mesh_import
tests_unit_test_mesh_import_SOURCES = tests/unit/test_mesh_import.c
tests_unit_test_mesh_import_LDADD = $(SCN_LIBS)
EXTRA_DIST += tests/unit/meshes/ascii.ply tests/unit/meshes/bad_index.obj \
	tests/unit/meshes/bad_number.ply tests/unit/meshes/binary.ply tests/unit/meshes/empty.obj \
	tests/unit/meshes/garbage.bin tests/unit/meshes/lines.obj tests/unit/meshes/mixed.obj \
	tests/unit/meshes/nodes.gltf tests/unit/meshes/normals.obj \
	tests/unit/meshes/partial_normals.obj tests/unit/meshes/quad.obj tests/unit/meshes/square.obj \
	tests/unit/meshes/truncated.ply
check_PROGRAMS += tests/unit/test_image
TESTS += tests/unit/test_image
tests_unit_test_image_SOURCES = tests/unit/test_image.c
tests_unit_test_image_CPPFLAGS = $(AM_CPPFLAGS) $(PNG_CFLAGS)
tests_unit_test_image_LDADD = $(SCN_LIBS)
tests_unit_test_image_CPPFLAGS += $(EXR_CFLAGS)
check_PROGRAMS += tests/unit/test_sampler
TESTS += tests/unit/test_sampler
tests_unit_test_sampler_SOURCES = tests/unit/test_sampler.c
tests_unit_test_sampler_LDADD = $(SCN_LIBS)
check_PROGRAMS += tests/unit/test_bvh
TESTS += tests/unit/test_bvh
tests_unit_test_bvh_SOURCES = tests/unit/test_bvh.c
tests_unit_test_bvh_LDADD = $(SCN_LIBS)
check_PROGRAMS += tests/unit/test_shape
TESTS += tests/unit/test_shape
tests_unit_test_shape_SOURCES = tests/unit/test_shape.c
tests_unit_test_shape_LDADD = $(SCN_LIBS)
EXTRA_DIST += tests/unit/meshes/cut_faces.ply tests/unit/meshes/no_end_header.ply \
	tests/unit/meshes/empty_faces.ply tests/unit/meshes/unknown_lines.ply \
	tests/unit/meshes/infinite.gltf tests/unit/meshes/infinite.obj
check_PROGRAMS += tests/unit/test_imgdiff
TESTS += tests/unit/test_imgdiff
tests_unit_test_imgdiff_SOURCES = tests/unit/test_imgdiff.c
tests_unit_test_imgdiff_LDADD = $(SCN_LIBS)
check_PROGRAMS += tests/unit/test_crash
TESTS += tests/unit/test_crash
tests_unit_test_crash_SOURCES = tests/unit/test_crash.c
tests_unit_test_crash_LDADD = $(SCN_LIBS)
check_PROGRAMS += tests/unit/test_csg
TESTS += tests/unit/test_csg
tests_unit_test_csg_SOURCES = tests/unit/test_csg.c
tests_unit_test_csg_LDADD = $(SCN_LIBS)
check_PROGRAMS += tests/unit/test_torus
TESTS += tests/unit/test_torus
tests_unit_test_torus_SOURCES = tests/unit/test_torus.c tests/unit/torus_ref.h
tests_unit_test_torus_LDADD = $(SCN_LIBS)
EXTRA_DIST += tests/unit/meshes/materials.obj tests/unit/meshes/materials.mtl tests/unit/meshes/glass.obj \
	tests/unit/meshes/glass.mtl tests/unit/meshes/uv.ply tests/unit/meshes/st.ply \
	tests/unit/meshes/textured.gltf tests/unit/meshes/embedded.gltf tests/unit/meshes/textures/checker.png
check_PROGRAMS += tests/unit/test_texture
TESTS += tests/unit/test_texture
tests_unit_test_texture_SOURCES = tests/unit/test_texture.c
tests_unit_test_texture_LDADD = $(SCN_LIBS)
check_PROGRAMS += tests/unit/test_light
TESTS += tests/unit/test_light
tests_unit_test_light_SOURCES = tests/unit/test_light.c
tests_unit_test_light_LDADD = $(SCN_LIBS)

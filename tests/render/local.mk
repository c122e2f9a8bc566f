# tests/render/local.mk: renders with known answers. A test is NAME.scn + NAME.expect,
# whose pixel values are worked out by hand from LANGUAGE.md's shading model (each
# .expect says how), checked by probe.
check_PROGRAMS += tests/render/probe
tests_render_probe_SOURCES = tests/render/probe.c tests/render/probe_hit.c tests/render/probe_hit.h
tests_render_probe_LDADD = $(SCN_LIBS)
RENDER_TESTS = tests/render/emit.scn tests/render/blinn_phong.scn
RENDER_TESTS += tests/render/lambert_60.scn tests/render/point_light.scn tests/render/fade.scn tests/render/spotlight.scn tests/render/area_weights.scn tests/render/lens_edge.scn tests/render/two_lights.scn tests/render/default_material.scn tests/render/light_behind.scn tests/render/two_sided.scn
RENDER_TESTS += tests/render/highlight.scn tests/render/highlight_filtered.scn tests/render/shadowless.scn
RENDER_TESTS += tests/render/shadow.scn tests/render/shadow_point.scn tests/render/filtered_shadow.scn tests/render/shadow_inside.scn
RENDER_TESTS += tests/render/mirror.scn tests/render/mirror_sky.scn tests/render/mirror_sphere.scn tests/render/mirrors_depth1.scn tests/render/mirrors_depth2.scn tests/render/mirrors_depth5.scn
RENDER_TESTS += tests/render/mirrors_default.scn tests/render/mirrors_depth256.scn tests/render/mirrors_tiny.scn tests/render/refract_tiny.scn tests/render/acne_far.scn tests/render/acne_sphere.scn
RENDER_TESTS += tests/render/refract_slab.scn tests/render/refract_slab_depth2.scn tests/render/refract_sphere.scn tests/render/refract_ior1.scn tests/render/refract_offaxis.scn tests/render/refract_enter.scn tests/render/refract_exit.scn tests/render/tir.scn
RENDER_TESTS += tests/render/fresnel_normal.scn tests/render/fresnel_60.scn tests/render/fresnel_exit.scn tests/render/fresnel_opaque.scn
RENDER_TESTS += tests/render/pattern_gradient.scn tests/render/pattern_radial.scn tests/render/bump_mirror.scn
RENDER_TESTS += tests/render/checker.scn tests/render/checker_translate.scn tests/render/checker_scale.scn tests/render/checker_sphere.scn tests/render/checker_bias.scn tests/render/checker_below.scn
RENDER_TESTS += tests/render/sky_up.scn tests/render/sky_horizon.scn tests/render/sky_mid.scn tests/render/sky_constant.scn tests/render/skybox_png.scn tests/render/skybox_rotate.scn tests/render/skybox_srgb.scn tests/render/skybox_exr.scn
RENDER_TESTS += tests/render/camera_fov.scn tests/render/default_camera.scn tests/render/camera_ortho.scn tests/render/camera_ortho_samples.scn
RENDER_TESTS += tests/render/triangle.scn tests/render/mesh_flat.scn tests/render/mesh_smooth.scn tests/render/mesh_normals.scn tests/render/mesh_transform.scn tests/render/mesh_obj.scn tests/render/mesh_ply.scn
RENDER_TESTS += tests/render/transforms.scn tests/render/plane_transform.scn
RENDER_TESTS += tests/render/samples_grid4.scn tests/render/samples_grid16.scn tests/render/samples_jittered.scn tests/render/samples_random.scn tests/render/samples_poisson.scn
RENDER_TESTS += tests/render/plan_depth1.scn
RENDER_TESTS += tests/render/fog.scn tests/render/fog_inside.scn

# samples per pixel; see the test's .scn)
TESTS += $(RENDER_TESTS)
EXTRA_DIST += $(RENDER_TESTS) $(RENDER_TESTS:.scn=.expect)
# what the tests read (skybox maps, mesh files), the script that wrote the maps, and the
# tests left out of RENDER_TESTS above until the renderer passes them
EXTRA_DIST += tests/render/sky_4x2.png tests/render/sky_srgb.png tests/render/sky_2x1.exr \
	tests/render/tri_normals.obj tests/render/tri_normals.ply tests/render/mkimages.py \
	tests/render/samples_adaptive.scn tests/render/samples_adaptive.expect
RENDER_TESTS += tests/render/samples_adaptive.scn

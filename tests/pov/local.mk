# tests/pov/local.mk: the reference suite. Each NAME.scn is rendered by scn and, through
# `scn pov`, by POV-Ray 3.7, and the two images must agree (tests/pov/run-pov: at most 0.2%
# of the pixels off by more than 2/255, a mean error of at most 0.5/255). Together the
# scenes use every feature of the language; each one's first line says what it covers.
# Without povray the tests skip.
# env.exr (the sky of sky_exr.scn) is `scn render env.scn -o env.exr` (half float) of:
#   camera { location <0, 1, -4>  look_at <0, 1, 0>  fov 120  resolution 128, 64 }
#   light  { position <-3, 6, -4>  intensity 0.9 }
#   skybox { zenith <0.1, 0.25, 0.7>  horizon <0.85, 0.8, 0.7> }
#   plane  { <0, 1, 0>, 0  material { diffuse checker(<0.5, 0.6, 0.3>, <0.2, 0.35, 0.1>, 1) } }
#   sphere { <-2, 1.5, 2>, 1  material { diffuse 0  emit <0.95, 0.7, 0.3> } }
#   sphere { <2, 1, 1>, 1  material { diffuse <0.2, 0.4, 0.9> } }
POV_TESTS = \
	tests/pov/camera_default.scn \
	tests/pov/camera_ortho.scn \
	tests/pov/camera_ortho_grid.scn \
	tests/pov/camera_inside_glass.scn \
	tests/pov/camera_up.scn \
	tests/pov/camera_wide.scn \
	tests/pov/camera_zup.scn \
	tests/pov/checker_objects.scn \
	tests/pov/checker_planes.scn \
	tests/pov/csg_difference.scn \
	tests/pov/lang_colonnade.scn \
	tests/pov/csg_glass.scn \
	tests/pov/csg_intersection.scn \
	tests/pov/csg_inverse.scn \
	tests/pov/csg_materials.scn \
	tests/pov/csg_merge.scn \
	tests/pov/csg_mesh.scn \
	tests/pov/csg_nested.scn \
	tests/pov/csg_union.scn \
	tests/pov/emit.scn \
	tests/pov/fog.scn \
	tests/pov/fog_depth.scn \
	tests/pov/fresnel.scn \
	tests/pov/glass.scn \
	tests/pov/glass_plane.scn \
	tests/pov/grid4.scn \
	tests/pov/grid9.scn \
	tests/pov/lights_coloured.scn \
	tests/pov/lights_directional.scn \
	tests/pov/lights_area.scn \
	tests/pov/lights_area_circular.scn \
	tests/pov/lights_fade.scn \
	tests/pov/lights_shadowless.scn \
	tests/pov/lights_spotlight.scn \
	tests/pov/loops.scn \
	tests/pov/materials.scn \
	tests/pov/materials_layered.scn \
	tests/pov/mesh_files.scn \
	tests/pov/mesh_inline.scn \
	tests/pov/mesh_instances.scn \
	tests/pov/mirrors_depth1.scn \
	tests/pov/mirrors_depth10.scn \
	tests/pov/mirrors_depth3.scn \
	tests/pov/sky_color.scn \
	tests/pov/sky_exr.scn \
	tests/pov/sky_gradient.scn \
	tests/pov/sky_png.scn \
	tests/pov/solid_box.scn \
	tests/pov/solid_cone.scn \
	tests/pov/solid_cylinder.scn \
	tests/pov/solid_disc.scn \
	tests/pov/solid_ellipsoid.scn \
	tests/pov/solid_mirror.scn \
	tests/pov/solid_torus.scn \
	tests/pov/specular.scn \
	tests/pov/tir.scn \
	tests/pov/transforms.scn \
	tests/pov/transforms_mirror.scn \
	tests/pov/transmit_ior1.scn \
	tests/pov/triangles.scn \
	tests/pov/whitted.scn
TESTS += $(POV_TESTS) tests/pov/statistical.sh
EXTRA_DIST += $(POV_TESTS) tests/pov/statistical.sh tests/pov/run-pov tests/pov/mirrors.inc tests/pov/palette.inc \
	tests/pov/octa.obj tests/pov/env.exr
# The surfaces of LANGUAGE.md section 11 (patterns, image maps, mesh files' materials): their
# small textures are written by tests/pov/surface_images.py.
POV_SURFACE_TESTS = \
	tests/pov/surface_gradient.scn \
	tests/pov/surface_image_planar.scn \
	tests/pov/surface_image_uv.scn \
	tests/pov/surface_image_wrap.scn \
	tests/pov/surface_leopard.scn \
	tests/pov/surface_marble.scn \
	tests/pov/surface_materials.scn \
	tests/pov/surface_mesh_files.scn \
	tests/pov/surface_onion.scn \
	tests/pov/surface_radial.scn \
	tests/pov/surface_wood.scn
TESTS += $(POV_SURFACE_TESTS)
EXTRA_DIST += $(POV_SURFACE_TESTS) tests/pov/surface_images.py tests/pov/surface_tex.png \
	tests/pov/surface_linear.png tests/pov/surface_g22.png tests/pov/surface_mtl.png \
	tests/pov/surface_box.obj tests/pov/surface_box.mtl tests/pov/surface_quad.gltf

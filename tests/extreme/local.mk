# tests/extreme/local.mk: stiff and extreme scenes (issue 5): world offsets and scales,
# tiny and far spheres, huge ground spheres, lights on and in objects, grazing light and
# view, rays along shared mesh edges and BVH slab planes, camera extremes, deep mirrors,
# total internal reflection, the shadow terminator of a smooth low-poly mesh, the stiff
# cases of section 9's shapes (thin tori face-on and edge-on, far tori, a flattened
# ellipsoid, a cylinder seen along its axis, flush cutters and coinciding CSG members),
# textures at their extremes (overflowing patterns, scales of 1e-300 and 1e300, a textured
# sphere at 1e15), and non-finite or degenerate input. Each NAME.scn has the property NAME.expect states (an
# analytic mask, or equality with a well-conditioned twin), or is refused as NAME.err
# says; tests/extreme/run-extreme checks it, and every render must count 0 non-finite
# radiance values. tests/extreme/compare-pov checks the same properties on POV-Ray's
# renders (not part of make check).
EXTREME_TESTS = \
	tests/extreme/texture_overflow.scn \
	tests/extreme/texture_extremes.scn \
	tests/extreme/axis_rays_neg.scn \
	tests/extreme/axis_rays_pos.scn \
	tests/extreme/axis_rays_x.scn \
	tests/extreme/coincident_intersection.scn \
	tests/extreme/coincident_merge.scn \
	tests/extreme/coplanar.scn \
	tests/extreme/cube_corner.scn \
	tests/extreme/cylinder_axis.scn \
	tests/extreme/degenerate.scn \
	tests/extreme/edge_on.scn \
	tests/extreme/ellipsoid_1e-3.scn \
	tests/extreme/ellipsoid_edge_1e-3.scn \
	tests/extreme/far_sphere_1e6.scn \
	tests/extreme/far_sphere_3e6.scn \
	tests/extreme/flush_hole.scn \
	tests/extreme/flush_pocket.scn \
	tests/extreme/flush_pocket_moved.scn \
	tests/extreme/fov_179.9.scn \
	tests/extreme/fov_1e-6.scn \
	tests/extreme/glass_cube_tir.scn \
	tests/extreme/glass_sphere_1e6.scn \
	tests/extreme/grazing_light.scn \
	tests/extreme/grazing_sphere.scn \
	tests/extreme/grazing_view.scn \
	tests/extreme/ground_1e12.scn \
	tests/extreme/ground_1e6.scn \
	tests/extreme/ground_3e9.scn \
	tests/extreme/horizon_far.scn \
	tests/extreme/huge_mesh.scn \
	tests/extreme/huge_sphere.scn \
	tests/extreme/image_1x10000.scn \
	tests/extreme/light_above_1e-6.scn \
	tests/extreme/light_above_1e-8.scn \
	tests/extreme/light_in_cube.scn \
	tests/extreme/light_in_sphere.scn \
	tests/extreme/light_on_sphere.scn \
	tests/extreme/literal_1e400.scn \
	tests/extreme/mesh_fan.scn \
	tests/extreme/mesh_grid.scn \
	tests/extreme/mirrors_256.scn \
	tests/extreme/mirrors_close.scn \
	tests/extreme/nonfinite_loop.scn \
	tests/extreme/offset_1e6.scn \
	tests/extreme/offset_1e9.scn \
	tests/extreme/offset_3p7e7.scn \
	tests/extreme/offset_scale.scn \
	tests/extreme/overflow.scn \
	tests/extreme/prism_tir.scn \
	tests/extreme/scale_1e-4.scn \
	tests/extreme/scale_1e-90.scn \
	tests/extreme/scale_1e5.scn \
	tests/extreme/scale_1e90.scn \
	tests/extreme/scale_3e-6.scn \
	tests/extreme/scale_7e7.scn \
	tests/extreme/subnormal_dirs.scn \
	tests/extreme/terminator.scn \
	tests/extreme/tiny_radius.scn \
	tests/extreme/tiny_sphere_2e-6.scn \
	tests/extreme/tiny_sphere_5e-6.scn \
	tests/extreme/torus_edge_1e-3.scn \
	tests/extreme/torus_edge_1e-4.scn \
	tests/extreme/torus_face_1e-3.scn \
	tests/extreme/torus_face_1e-4.scn \
	tests/extreme/torus_far_1e6.scn \
	tests/extreme/torus_far_1e9.scn \
	tests/extreme/fade_extremes.scn \
	tests/extreme/spot_hard_edge.scn \
	tests/extreme/fog_light_inside.scn \
	tests/extreme/area_straddle_1e-6.scn
TESTS += $(EXTREME_TESTS) tests/extreme/accel-grid.sh
EXTREME_EXPECT = \
	tests/extreme/axis_rays_neg.expect \
	tests/extreme/axis_rays_pos.expect \
	tests/extreme/axis_rays_x.expect \
	tests/extreme/coincident_intersection.expect \
	tests/extreme/coincident_merge.expect \
	tests/extreme/coplanar.expect \
	tests/extreme/cube_corner.expect \
	tests/extreme/cylinder_axis.expect \
	tests/extreme/degenerate.expect \
	tests/extreme/edge_on.expect \
	tests/extreme/ellipsoid_1e-3.expect \
	tests/extreme/ellipsoid_edge_1e-3.expect \
	tests/extreme/far_sphere_1e6.expect \
	tests/extreme/far_sphere_3e6.expect \
	tests/extreme/flush_hole.expect \
	tests/extreme/flush_pocket.expect \
	tests/extreme/flush_pocket_moved.expect \
	tests/extreme/fov_179.9.expect \
	tests/extreme/fov_1e-6.expect \
	tests/extreme/glass_cube_tir.expect \
	tests/extreme/glass_sphere_1e6.expect \
	tests/extreme/grazing_light.expect \
	tests/extreme/grazing_sphere.expect \
	tests/extreme/grazing_view.expect \
	tests/extreme/ground_1e12.expect \
	tests/extreme/ground_1e6.expect \
	tests/extreme/ground_3e9.expect \
	tests/extreme/horizon_far.expect \
	tests/extreme/image_1x10000.expect \
	tests/extreme/light_above_1e-6.expect \
	tests/extreme/light_above_1e-8.expect \
	tests/extreme/light_in_cube.expect \
	tests/extreme/light_in_sphere.expect \
	tests/extreme/light_on_sphere.expect \
	tests/extreme/mesh_fan.expect \
	tests/extreme/mesh_grid.expect \
	tests/extreme/mirrors_256.expect \
	tests/extreme/mirrors_close.expect \
	tests/extreme/offset_1e6.expect \
	tests/extreme/offset_1e9.expect \
	tests/extreme/offset_3p7e7.expect \
	tests/extreme/offset_scale.expect \
	tests/extreme/prism_tir.expect \
	tests/extreme/scale_1e-4.expect \
	tests/extreme/scale_1e-90.expect \
	tests/extreme/scale_1e5.expect \
	tests/extreme/scale_1e90.expect \
	tests/extreme/scale_3e-6.expect \
	tests/extreme/scale_7e7.expect \
	tests/extreme/subnormal_dirs.expect \
	tests/extreme/terminator.expect \
	tests/extreme/tiny_radius.expect \
	tests/extreme/tiny_sphere_2e-6.expect \
	tests/extreme/tiny_sphere_5e-6.expect \
	tests/extreme/torus_edge_1e-3.expect \
	tests/extreme/torus_edge_1e-4.expect \
	tests/extreme/torus_face_1e-3.expect \
	tests/extreme/torus_face_1e-4.expect \
	tests/extreme/torus_far_1e6.expect \
	tests/extreme/torus_far_1e9.expect \
	tests/extreme/texture_overflow.expect \
	tests/extreme/texture_extremes.expect \
	tests/extreme/fade_extremes.expect \
	tests/extreme/spot_hard_edge.expect \
	tests/extreme/fog_light_inside.expect \
	tests/extreme/area_straddle_1e-6.expect
EXTREME_REFUSED = tests/extreme/huge_mesh.err tests/extreme/huge_sphere.err tests/extreme/literal_1e400.err \
	tests/extreme/nonfinite_loop.err tests/extreme/overflow.err
EXTRA_DIST += $(EXTREME_TESTS) $(EXTREME_EXPECT) $(EXTREME_REFUSED) \
	tests/extreme/run-extreme tests/extreme/compare-pov tests/extreme/accel-grid.sh \
	tests/extreme/world.inc tests/extreme/torus.inc tests/extreme/ground.inc tests/extreme/dark.inc tests/extreme/grazing.inc \
	tests/extreme/axis_grid.inc tests/extreme/subnormal_dirs.inc \
	tests/extreme/terminator.inc tests/extreme/icosphere.inc tests/extreme/terminator_twin.scn \
	tests/extreme/grazing_sphere_twin.scn \
	tests/extreme/area_straddle_twin.scn \
	tests/extreme/ground_plane.scn \
	tests/extreme/no_light.scn \
	tests/extreme/subnormal_dirs_twin.scn \
	tests/extreme/torus_twin.scn \
	tests/extreme/world_twin.scn \
	tests/extreme/texture_overflow_twin.scn

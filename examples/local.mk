# examples/local.mk: the example scenes; each must check clean (no errors, no warnings).
EXAMPLES = examples/whitted.scn
EXAMPLES += examples/manpage.scn
EXAMPLES += examples/bunny.scn
TESTS += $(EXAMPLES)
EXTRA_DIST += $(EXAMPLES)
EXTRA_DIST += examples/bunny.ply
EXAMPLES += examples/skybox.scn
EXAMPLES += examples/materials.scn
EXAMPLES += examples/lights.scn
EXAMPLES += examples/triangles.scn
EXAMPLES += examples/sampling.scn
EXAMPLES += examples/loops.scn
EXAMPLES += examples/temple.scn
EXTRA_DIST += examples/sky.png examples/sky.pov examples/temple.png
EXAMPLES += examples/tree.scn
EXAMPLES += examples/colonnade.scn
EXAMPLES += examples/orbit.scn

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
EXTRA_DIST += examples/tree.png examples/colonnade.png
EXAMPLES += examples/textures.scn examples/crate-texture.scn
EXTRA_DIST += examples/textures.png examples/picture.png examples/crate.obj examples/crate.mtl examples/crate.png
EXAMPLES += examples/still_life.scn
EXTRA_DIST += examples/still_life.png
# scn over a cluster: Slurm job arrays and GNU parallel (parts and scn merge), MPI with
# srun; tests/cli/cluster.sh runs each against stand-ins
EXTRA_DIST += examples/cluster/part.sbatch examples/cluster/render-frame.sh examples/cluster/parallel.sh \
	examples/cluster/mpi.sbatch

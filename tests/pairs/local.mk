# tests/pairs/local.mk: scenes written with LANGUAGE.md section 10's forms, each with a flat
# twin written without them that must render the same bytes (tests/pairs/pairs.sh).
TESTS += tests/pairs/pairs.sh
EXTRA_DIST += tests/pairs/pairs.sh tests/pairs/pyramid2.obj
EXTRA_DIST += tests/pairs/arrays_for.scn tests/pairs/arrays_for.flat.scn
EXTRA_DIST += tests/pairs/arrays_index.scn tests/pairs/arrays_index.flat.scn
EXTRA_DIST += tests/pairs/boolean.scn tests/pairs/boolean.flat.scn
EXTRA_DIST += tests/pairs/colonnade.scn tests/pairs/colonnade.flat.scn
EXTRA_DIST += tests/pairs/csg_members.scn tests/pairs/csg_members.flat.scn
EXTRA_DIST += tests/pairs/function.scn tests/pairs/function.flat.scn
EXTRA_DIST += tests/pairs/ifelse.scn tests/pairs/ifelse.flat.scn
EXTRA_DIST += tests/pairs/nested.scn tests/pairs/nested.flat.scn
EXTRA_DIST += tests/pairs/strings.scn tests/pairs/strings.flat.scn
EXTRA_DIST += tests/pairs/ternary.scn tests/pairs/ternary.flat.scn
EXTRA_DIST += tests/pairs/tree.scn tests/pairs/tree.flat.scn
EXTRA_DIST += tests/pairs/material_values.scn tests/pairs/material_values.flat.scn
EXTRA_DIST += tests/pairs/csg_first.scn tests/pairs/csg_first.flat.scn

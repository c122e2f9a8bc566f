# tests/fuzz/local.mk: fuzzing. `make fuzz` builds the libFuzzer harnesses with clang,
# apart from the main build and whatever CC it uses, and runs each for FUZZ_SECONDS
# (fuzz.sh; 0 only builds them; FUZZ_TARGETS picks harnesses, FUZZ_OPTIONS adds libFuzzer
# flags, e.g. "-fork=1 -ignore_crashes=1" to go on after a finding). The harness
# binaries are not part of `make` or `make check`; the saved corpora and reproducers are:
# replay.sh replays them through the same harness sources built with the normal
# compiler and replay.c's main().
FUZZ_CC = clang
FUZZ_SECONDS = 60
FUZZ_TARGETS = scene mesh png exr part
FUZZ_OPTIONS =
# the part harness reaches into the command: a part's reading and checks (tile_part.c)
# and what they call
FUZZ_CMD_FILES = src/tile.c src/tile_part.c src/cli.c src/pov_hint.c
fuzz: all
	@FUZZ_SOURCES='$(SCN_LIB_FILES) $(FUZZ_CMD_FILES)' \
	FUZZ_LIB_CFLAGS='$(ALL_INCLUDES) -I$(srcdir)/src $(PNG_CFLAGS) $(EXR_CFLAGS) $(ASSIMP_CFLAGS) $(XXHASH_CFLAGS)' \
	FUZZ_LIBS='$(PNG_LIBS) $(EXR_LIBS) $(ASSIMP_LIBS) $(XXHASH_LIBS)' \
	FUZZ_CC='$(FUZZ_CC)' FUZZ_SECONDS='$(FUZZ_SECONDS)' FUZZ_TARGETS='$(FUZZ_TARGETS)' \
	FUZZ_OPTIONS='$(FUZZ_OPTIONS)' top_srcdir='$(abs_top_srcdir)' top_builddir='$(abs_top_builddir)' \
	$(SHELL) $(srcdir)/tests/fuzz/fuzz.sh
.PHONY: fuzz
clean-local: clean-fuzz
clean-fuzz:
	rm -rf tests/fuzz/obj tests/fuzz/work tests/fuzz/seed tests/fuzz/findings tests/fuzz/tmp \
		tests/fuzz/scene.dict $(FUZZ_TARGETS:%=tests/fuzz/fuzz_%)
.PHONY: clean-fuzz

# the harnesses with replay.c's main(), for replay.sh
FUZZ_REPLAY_CPPFLAGS = $(AM_CPPFLAGS) -I$(srcdir)/tests/fuzz
FUZZ_REPLAY_SOURCES = tests/fuzz/replay.c tests/fuzz/fuzz_file.c tests/fuzz/fuzz.h
check_PROGRAMS += tests/fuzz/replay_scene tests/fuzz/replay_mesh tests/fuzz/replay_png \
	tests/fuzz/replay_exr tests/fuzz/replay_part
tests_fuzz_replay_scene_SOURCES = tests/fuzz/fuzz_scene.c $(FUZZ_REPLAY_SOURCES)
tests_fuzz_replay_scene_CPPFLAGS = $(FUZZ_REPLAY_CPPFLAGS)
tests_fuzz_replay_scene_LDADD = $(SCN_LIBS)
tests_fuzz_replay_mesh_SOURCES = tests/fuzz/fuzz_mesh.c $(FUZZ_REPLAY_SOURCES)
tests_fuzz_replay_mesh_CPPFLAGS = $(FUZZ_REPLAY_CPPFLAGS)
tests_fuzz_replay_mesh_LDADD = $(SCN_LIBS)
tests_fuzz_replay_png_SOURCES = tests/fuzz/fuzz_png.c tests/fuzz/fuzz_image.h $(FUZZ_REPLAY_SOURCES)
tests_fuzz_replay_png_CPPFLAGS = $(FUZZ_REPLAY_CPPFLAGS)
tests_fuzz_replay_png_LDADD = $(SCN_LIBS)
tests_fuzz_replay_exr_SOURCES = tests/fuzz/fuzz_exr.c tests/fuzz/fuzz_image.h $(FUZZ_REPLAY_SOURCES)
tests_fuzz_replay_exr_CPPFLAGS = $(FUZZ_REPLAY_CPPFLAGS)
tests_fuzz_replay_exr_LDADD = $(SCN_LIBS)
tests_fuzz_replay_part_SOURCES = tests/fuzz/fuzz_part.c $(FUZZ_CMD_FILES) $(FUZZ_REPLAY_SOURCES)
tests_fuzz_replay_part_CPPFLAGS = $(FUZZ_REPLAY_CPPFLAGS) -I$(srcdir)/src $(XXHASH_CFLAGS)
tests_fuzz_replay_part_LDADD = $(SCN_LIBS)
TESTS += tests/fuzz/replay.sh
EXTRA_DIST += tests/fuzz/replay.sh tests/fuzz/fuzz.sh tests/fuzz/lsan.supp tests/fuzz/corpus \
	tests/fuzz/regress

# bench/local.mk: programs built on demand only (bench/run, or make bench/NAME): never
# part of `make` or `make check`. embree_compare needs libembree-dev, which bench/run
# installs.
EXTRA_PROGRAMS = bench/embree_compare bench/plot_csv bench/torus_bench bench/noise_bench
bench_embree_compare_SOURCES = bench/embree_compare.c
bench_embree_compare_CPPFLAGS = $(AM_CPPFLAGS) -I$(srcdir)/tests/unit
bench_embree_compare_LDADD = $(SCN_LIBS) -lembree3
bench_plot_csv_SOURCES = bench/plot_csv.c src/plot.c src/plot.h
bench_plot_csv_CPPFLAGS = $(AM_CPPFLAGS) -I$(srcdir)/src
bench_plot_csv_LDADD = $(SCN_LIBS)
# torus_bench: torus_roots against sphere_intersect and a closed-form Ferrari solver
bench_torus_bench_SOURCES = bench/torus_bench.c tests/unit/torus_ref.h
bench_torus_bench_CPPFLAGS = $(AM_CPPFLAGS) -I$(srcdir)/tests/unit
bench_torus_bench_LDADD = $(SCN_LIBS)
# noise_bench: the noise's calls and octave sums, in ns
bench_noise_bench_SOURCES = bench/noise_bench.c
bench_noise_bench_LDADD = $(SCN_LIBS)
EXTRA_DIST += bench/run bench/bench.py bench/scenes.py bench/scaling.svg

# bench/local.mk: programs that only bench/run builds, on demand (make bench/NAME): never
# part of `make` or `make check`. embree_compare needs libembree-dev, which bench/run
# installs.
EXTRA_PROGRAMS = bench/embree_compare bench/plot_csv
bench_embree_compare_SOURCES = bench/embree_compare.c
bench_embree_compare_CPPFLAGS = $(AM_CPPFLAGS) -I$(srcdir)/tests/unit
bench_embree_compare_LDADD = $(SCN_LIBS) -lembree3
bench_plot_csv_SOURCES = bench/plot_csv.c src/plot.c src/plot.h
bench_plot_csv_CPPFLAGS = $(AM_CPPFLAGS) -I$(srcdir)/src
bench_plot_csv_LDADD = $(SCN_LIBS)
EXTRA_DIST += bench/run bench/bench.py bench/scenes.py bench/scaling.svg

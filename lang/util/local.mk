# lang/util/local.mk: what every layer uses and that uses nothing above it.
UTIL_INCLUDES = -I$(srcdir)/%D%
noinst_LIBRARIES += lang/util/libscnutil.a
lang_util_libscnutil_a_CPPFLAGS = $(BASE_CPPFLAGS) $(UTIL_INCLUDES)
lang_util_libscnutil_a_SOURCES = %D%/xalloc.c %D%/xalloc.h %D%/cleanup.c %D%/cleanup.h %D%/clock.c %D%/clock.h \
	%D%/memory.c %D%/memory.h %D%/outfile.c %D%/outfile.h

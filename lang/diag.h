/* diag.h: the source files of a run and the only code that prints diagnostics.
 * A span is a pair of byte offsets in one global space in which every loaded file
 * (the scene and each include) occupies its own range, so a span needs no file field. */
#ifndef SCN_DIAG_H
#define SCN_DIAG_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

struct span {
	uint32_t start, end; /* [start, end) in the global offset space */
};

struct source {
	char *path;          /* as the user or the include named it, for messages */
	char *dir;           /* directory that relative paths in this file start from */
	char *text;          /* the whole file, NUL-terminated; owned */
	uint32_t len;
	uint32_t base;       /* global offset of text[0] */
	bool included;       /* true when an include statement loaded it */
	struct span include_site;
	uint32_t *lines;     /* start offset of each line, computed on first use */
	uint32_t nlines;
};

enum diag_level { DIAG_ERROR, DIAG_WARNING, DIAG_NOTE };

/* A diagnostic held back until diag_flush, with the notes that follow it. */
struct diag_record {
	uint32_t *key;       /* reading-order position: include sites from the top file, then the offset */
	unsigned nkey;
	size_t seq;          /* order of reporting, for ties */
	char *text;
};

struct diag {
	FILE *out;
	struct diag_record *records;
	size_t nrecords, cap_records;
	struct source **files;
	size_t nfiles, cap;
	uint32_t next_base;
	int errors, warnings;
	int max_errors;      /* one error more than this stops the run: diag_stopped() */
	bool stopped;
	bool dropped;        /* the last error or warning was not printed, nor are its notes */
	bool stop_told;      /* the "too many errors" line was printed */
	bool warnings_told;  /* the count of warnings not shown was printed */
};

/* Total bytes of source the offset space (all files, includes counted each time) may hold. */
#define DIAG_MAX_SOURCE_BYTES (256u << 20)

void diag_init(struct diag *d, FILE *out);
/* Flushes, then releases the sources. */
void diag_fini(struct diag *d);
/* Prints the diagnostics reported so far in reading order: by position in the scene,
 * a position in an included file counting as its include statement's. The phases
 * (syntax, names, values) report in their own order; the user reads the file's. */
void diag_flush(struct diag *d);

/* The state of the diagnostics and the files at one moment, to go back to. */
struct diag_mark {
	size_t nrecords, nfiles;
	uint32_t next_base;
	int errors, warnings;
	bool stopped, dropped;
};
struct diag_mark diag_mark(const struct diag *d);
/* Whether what was reported since m would be printed the same had it been reported in
 * another order: warnings only (the order decides which errors count against the limit),
 * and no more of them than are shown. (Diagnostics at one place stay in the order they
 * were reported in; front end warnings at one place are all the same words.) */
bool diag_any_order(const struct diag *d, struct diag_mark m);
/* Forgets what was reported and the files registered since m (nothing was flushed
 * since): for a load that starts over another way. */
void diag_rewind(struct diag *d, struct diag_mark m);

/* Registers a loaded file; takes ownership of text (malloc'd, len bytes + NUL).
 * Returns the source, or NULL when the total would exceed DIAG_MAX_SOURCE_BYTES
 * (text is then freed). */
struct source *diag_add_source(struct diag *d, const char *path, char *text, uint32_t len,
                               const struct source *includer, struct span include_site);
/* The file that holds global offset off. */
const struct source *diag_source_at(const struct diag *d, uint32_t off);
/* 1-based line and byte column of off. */
void diag_line_col(const struct diag *d, uint32_t off, unsigned *line, unsigned *col);

void diag_report(struct diag *d, enum diag_level level, struct span sp, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
#define diag_error(d, sp, ...) diag_report((d), DIAG_ERROR, (sp), __VA_ARGS__)
#define diag_warning(d, sp, ...) diag_report((d), DIAG_WARNING, (sp), __VA_ARGS__)
#define diag_note(d, sp, ...) diag_report((d), DIAG_NOTE, (sp), __VA_ARGS__)
/* A message about no place in a scene: "scn: error: ...". */
void diag_plain(struct diag *d, enum diag_level level, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

static inline bool diag_stopped(const struct diag *d) { return d->stopped; }

static inline struct span diag_span_join(struct span a, struct span b)
{
	return (struct span){ a.start < b.start ? a.start : b.start, a.end > b.end ? a.end : b.end };
}

#endif

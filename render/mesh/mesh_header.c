/* mesh_header.c: checks on a mesh file's header before assimp 5.2 reads it:
 * - a PLY header must end: assimp's PLY reader loops forever on a header without an
 *   end_header line, as in a file cut short inside its header;
 * - the element counts a PLY or OFF header declares must fit in the file: assimp
 *   allocates for them up front (16 bytes and more per element), so a few bytes claiming
 *   10^9 vertices would have it ask for gigabytes, and fail, or worse, before it finds
 *   that the file holds none of them.
 * - a PLY header must declare each element once: assimp 5.2 writes past its buffers
 *   when an element comes again with a larger count (found by fuzzing; valgrind shows
 *   the write).
 * Nothing else is checked: these checks guard memory and time, and must not refuse a
 * file that assimp reads, such as a PLY with a header line it does not know.
 * Each element takes some bytes in the file, so a count beyond the file's size is a
 * malformed file, refused with the count in the message. */
#include "mesh_header.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "xalloc.h"

/* How much of a file holds its header: PLY's must end within it. */
#define HEADER_MAX 65536

int mesh_header_fail(char *err, size_t errlen, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(err, errlen, fmt, ap);
	va_end(ap);
	return 1;
}

/* The offset just past the "end_header" line that starts one of the first n bytes'
 * lines, give or take blanks, as assimp's PLY reader looks for it; 0 if there is none.
 * The line must end: assimp 5.2 can loop forever on a file that stops right after
 * end_header (found by fuzzing), and such a file has no vertices anyway. */
static size_t ply_header_end(const char *head, size_t n)
{
	static const char token[] = "end_header";
	const size_t len = sizeof token - 1;
	for (size_t i = 0; i < n; i++) {
		if (i > 0 && head[i - 1] != '\n')
			continue;
		size_t j = i;
		while (j < n && (head[j] == ' ' || head[j] == '\t'))
			j++;
		if (n - j < len || memcmp(head + j, token, len) != 0)
			continue;
		for (j += len; j < n && (head[j] == ' ' || head[j] == '\t' || head[j] == '\f'); j++)
			;
		if (j < n && (head[j] == '\n' || head[j] == '\r'))
			return j + 1;
	}
	return 0;
}

/* The bytes one value of a PLY type takes in a binary file; 0 for a name that is not a
 * PLY type. */
static unsigned ply_type_size(const char *type)
{
	static const struct { const char *name; unsigned size; } types[] = {
		{ "char", 1 }, { "uchar", 1 }, { "int8", 1 }, { "uint8", 1 },
		{ "short", 2 }, { "ushort", 2 }, { "int16", 2 }, { "uint16", 2 },
		{ "int", 4 }, { "uint", 4 }, { "int32", 4 }, { "uint32", 4 }, { "float", 4 },
		{ "float32", 4 }, { "double", 8 }, { "float64", 8 },
	};
	for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
		if (strcmp(type, types[i].name) == 0)
			return types[i].size;
	return 0;
}

/* The bytes one value of a PLY property line of k words takes at least: "property TYPE
 * NAME" its type's binary size, "property list COUNT-TYPE ITEM-TYPE NAME" its count's,
 * or two in ASCII (a digit and a blank); 0 for any other line, which ends the element's
 * properties for assimp (as a type it does not know does). */
static unsigned ply_property_bytes(char word[][64], int k, bool ascii)
{
	unsigned size = k == 3 ? ply_type_size(word[1]) :
	                k == 5 && strcmp(word[1], "list") == 0 && ply_type_size(word[3]) ? ply_type_size(word[2]) : 0;
	return size && ascii ? 2 : size;
}

/* Checks a PLY header (its first len bytes, up to and with its end_header line) for what
 * assimp 5.2 needs to keep its memory sound, and nothing more: an element's name comes
 * once (when one comes again with a larger count, assimp writes past its buffers: found
 * by fuzzing, valgrind shows the write), and the elements fit in the rest of the file,
 * size bytes (each element takes at least the bytes of its properties, up to the first
 * that assimp would not read, and at least one). Every other line is assimp's to judge:
 * it refuses a bad magic or format line itself, and skips the lines it does not know,
 * such as the "Created by Blender3D" line without "comment" of Blender 2.4's files. */
static int ply_counts(const char *head, size_t len, long long size, const char *path, char *err,
                      size_t errlen)
{
	bool ascii = true;             /* as the bound for a format assimp refuses */
	double need = 0;               /* bytes, for the elements before the current one */
	double count = 0;              /* of the current element */
	unsigned bytes = 0;            /* per current element, at least */
	bool counting = false;         /* the current element's properties have not ended */
	char name[64] = "";
	char (*seen)[64] = NULL;       /* the element names so far: each may come once */
	size_t nseen = 0, cap_seen = 0;
	int rc = 0;
	for (size_t i = 0, line_no = 0; i < len; line_no++) {
		const char *eol = memchr(head + i, '\n', len - i);
		size_t n = eol ? (size_t)(eol - (head + i)) : len - i;
		char line[256], word[5][64];
		snprintf(line, sizeof line, "%.*s", (int)(n < sizeof line ? n : sizeof line - 1), head + i);
		i += n + 1;
		int k = sscanf(line, "%63s %63s %63s %63s %63s", word[0], word[1], word[2], word[3], word[4]);
		if (k <= 0 || strcmp(word[0], "comment") == 0)
			continue;
		bool element = strcmp(word[0], "element") == 0;
		bool end = k == 1 && strcmp(word[0], "end_header") == 0;
		if (strcmp(word[0], "format") == 0)
			ascii = k < 2 || strncmp(word[1], "binary_", 7) != 0;
		if (!element && !end) {
			unsigned b = strcmp(word[0], "property") == 0 ? ply_property_bytes(word, k, ascii) : 0;
			counting = counting && b;
			bytes += counting ? b : 0;
			continue;
		}
		/* the element before this line is complete */
		need += count * (bytes ? bytes : 1);
		if (need > (double)size) {
			rc = mesh_header_fail(err, errlen, "malformed mesh file '%s': its PLY header declares %.0f "
			                      "'%s' elements, more than its %lld bytes can hold", path, count, name, size);
			break;
		}
		if (end)
			break;
		snprintf(name, sizeof name, "%s", k >= 2 ? word[1] : "");
		for (size_t e = 0; e < nseen && rc == 0; e++)
			if (strcmp(seen[e], name) == 0)
				rc = mesh_header_fail(err, errlen, "malformed mesh file '%s': line %zu of its PLY header, "
				                      "'%s', declares element '%s' again", path, line_no + 1, line, name);
		if (rc)
			break;
		xgrow((void **)&seen, &cap_seen, nseen + 1, sizeof *seen);
		memcpy(seen[nseen++], name, sizeof name);
		count = k >= 3 ? fmax(strtod(word[2], NULL), 0) : 0; /* assimp reads a minus sign as 0 */
		bytes = 0;
		counting = true;
	}
	free(seen);
	return rc;
}

/* Skips blanks, line ends and comment lines, as assimp's OFF reader does between tokens. */
static const char *off_next_token(const char *p)
{
	for (;;) {
		p += strspn(p, " \t\r\n");
		if (*p != '#')
			return p;
		p += strcspn(p, "\n");
	}
}

/* An OFF file's vertex and face counts must fit in the file, size bytes, at two bytes a
 * vertex or face at least. text is the file's start, NUL-terminated. The keyword is
 * read as assimp reads it: [ST][C][N][4][n]OFF, then the dimension after an n; a file
 * may leave the keyword out, and is then known as OFF by its extension (is_off). */
static int off_counts(const char *text, bool is_off, long long size, const char *path, char *err,
                      size_t errlen)
{
	const char *p = off_next_token(text);
	static const char *const prefixes[] = { "ST", "C", "N", "4", "n" };
	bool dimension = false;
	for (size_t i = 0; i < sizeof prefixes / sizeof prefixes[0]; i++) {
		size_t n = strlen(prefixes[i]);
		if (strncmp(p, prefixes[i], n) == 0) {
			p += n;
			dimension = prefixes[i][0] == 'n';
		}
	}
	if (strncmp(p, "OFF", 3) == 0)
		p += 3;
	else if (!is_off || dimension)
		return 0;              /* not OFF, or assimp refuses it */
	else
		p = text;
	double value[3];
	int want = dimension ? 3 : 2;
	for (int i = 0; i < want; i++) {
		p = off_next_token(p);
		char *after;
		value[i] = fmax(strtod(p, &after), 0);
		if (after == p)
			return 0;      /* no counts: assimp says so */
		p = after;
	}
	double vertices = value[want - 2], faces = value[want - 1];
	if (2 * (vertices + faces) > (double)size)
		return mesh_header_fail(err, errlen, "malformed mesh file '%s': its OFF header declares %.0f vertices "
				 "and %.0f faces, more than its %lld bytes can hold", path, vertices, faces, size);
	return 0;
}

/* Whether assimp's PLY reader would take the file of these first n bytes: it skips
 * blank lines before its "ply" (then hangs on some such files whose line goes on, found
 * by fuzzing), and any case will do. */
static bool is_ply(const char *head, size_t n)
{
	size_t i = 0;
	while (i < n && strchr(" \t\r\n", head[i]) && head[i])
		i++;
	return n - i >= 3 && strncasecmp(head + i, "ply", 3) == 0;
}

int mesh_header_check(const char *path, char *err, size_t errlen)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return mesh_header_fail(err, errlen, "cannot read mesh file '%s': %s", path, strerror(errno));
	struct stat st;
	long long size = fstat(fileno(f), &st) == 0 ? (long long)st.st_size : 0;
	char *head = xmalloc(HEADER_MAX);
	errno = 0;
	size_t n = fread(head, 1, HEADER_MAX, f);
	int e = ferror(f) ? (errno ? errno : EIO) : 0;
	fclose(f);
	int rc = 0;
	if (e) {
		rc = mesh_header_fail(err, errlen, "cannot read mesh file '%s': %s", path, strerror(e));
	} else if (is_ply(head, n)) {
		size_t end = ply_header_end(head, n);
		if (!end)
			rc = mesh_header_fail(err, errlen, "malformed mesh file '%s': the PLY header has no end_header line%s",
				       path, n == HEADER_MAX ? " in its first 64 KiB" : "");
		else
			rc = ply_counts(head, end, size - (long long)end, path, err, errlen);
	} else {
		const char *dot = strrchr(path, '.');
		head[n < HEADER_MAX ? n : HEADER_MAX - 1] = '\0';
		rc = off_counts(head, dot && strcasecmp(dot, ".off") == 0, size, path, err, errlen);
	}
	free(head);
	return rc;
}

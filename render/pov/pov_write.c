/* pov_write.c: how numbers, vectors, colours and strings are spelled in POV-Ray's scene
 * language, for the exporter's files: exact decimals, mesh2's single precision, and
 * escaped literals. */
#include "pov_write.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The shortest decimal that reads back as v exactly. */
void pov_num(FILE *f, double v)
{
	char buf[40];
	if (v == 0) {                  /* also -0 */
		fputs("0", f);
		return;
	}
	for (int prec = 15; prec <= 17; prec++) {
		snprintf(buf, sizeof buf, "%.*g", prec, v);
		if (strtod(buf, NULL) == v)
			break;
	}
	fputs(buf, f);
}

/* "x, y, z", the inside of a vector */
static void components(FILE *f, struct vec3 v)
{
	pov_num(f, v.x);
	fputs(", ", f);
	pov_num(f, v.y);
	fputs(", ", f);
	pov_num(f, v.z);
}

void pov_vec(FILE *f, struct vec3 v)
{
	fputc('<', f);
	components(f, v);
	fputc('>', f);
}

/* A vector in single precision, as mesh2 stores it: %.9g reads back as the same float.
 * A component beyond float's range is written as the double it is (never "inf", which
 * POV-Ray cannot parse): what POV-Ray makes of it is then its own doing. */
void pov_fvec(FILE *f, struct vec3 v)
{
	double c[3] = { v.x, v.y, v.z };
	for (int k = 0; k < 3; k++) {
		float single = (float)c[k];
		fprintf(f, isfinite(single) ? "%s%.9g" : "%s%.17g", k ? "," : "<", isfinite(single) ? (double)single : c[k]);
	}
	fputc('>', f);
}

/* A colour with a fourth channel (filter or transmit). */
void pov_vec4(FILE *f, struct vec3 v, double w)
{
	fputc('<', f);
	components(f, v);
	fputs(", ", f);
	pov_num(f, w);
	fputc('>', f);
}

/* A string literal: POV-Ray reads backslash escapes in strings. */
void pov_str(FILE *f, const char *s)
{
	fputc('"', f);
	for (; *s; s++) {
		if (*s == '"' || *s == '\\')
			fputc('\\', f);
		fputc(*s, f);
	}
	fputc('"', f);
}

/* A comment's text: one line, whatever the name holds. */
void pov_comment_text(FILE *f, const char *s)
{
	for (; *s; s++)
		fputc(*s == '\n' || *s == '\r' ? ' ' : *s, f);
}

/* "matrix <...>": POV-Ray's twelve numbers are the columns of scn's map, the translation
 * last. */
void pov_matrix(FILE *f, const struct affine *a)
{
	fputs("matrix <", f);
	for (int col = 0; col < 4; col++)
		for (int row = 0; row < 3; row++) {
			pov_num(f, a->m[row][col]);
			if (col < 3 || row < 2)
				fputs(", ", f);
		}
	fputc('>', f);
}

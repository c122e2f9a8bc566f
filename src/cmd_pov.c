/* cmd_pov.c: scn pov: load and lower a scene (at a moment of its animation with
 * --clock), then write the POV-Ray 3.7 scene that renders the same image
 * (render/pov/pov_export.c), atomically, or to standard output. */
#include "config.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "anim.h"
#include "cli.h"
#include "diag.h"
#include "load.h"
#include "lower.h"
#include "pov_export.h"
#include "scene_desc.h"
#include "xalloc.h"

enum { OPT_OUT, OPT_CLOCK, NOPTIONS };
static const struct cli_option options[NOPTIONS] = {
	[OPT_OUT] = { NULL, 'o', true },
	[OPT_CLOCK] = { "clock", 0, true },
};

int cmd_pov(const struct command *self, int argc, char **argv)
{
	const char *out_arg = NULL;
	struct load_frame at = { 0, 0 };
	bool clock_given = false;
	struct cli_parser p;
	cli_parser_init(&p, self, options, NOPTIONS, argc, argv);
	int o;
	while ((o = cli_next_option(&p)) >= 0) {
		if (o == OPT_OUT) {
			out_arg = p.value;
			continue;
		}
		if (anim_clock_arg(self, p.name, p.value, &at.clock)) /* OPT_CLOCK */
			return EXIT_USAGE;
		clock_given = true;
	}
	if (o == CLI_STOP)
		return p.status < 0 ? 0 : p.status;
	const char *scene = cli_scene(&p);
	if (!scene)
		return EXIT_USAGE;
	bool to_stdout = out_arg && strcmp(out_arg, "-") == 0;
	char *out = to_stdout || !out_arg ? cli_default_output(scene, ".pov") : xstrdup(out_arg);

	struct diag d;
	diag_init(&d, stderr);
	struct scene_desc desc;
	struct scene sc = { 0 };
	struct lower_times times;
	int rc = (int)load_scene(&d, scene, &at, &desc, NULL);
	if (rc == 0)
		rc = (int)lower_scene(&d, &desc, &sc, &times, -1);
	diag_flush(&d);
	if (rc == 0) {
		/* the .pov names the sky image relative to its own folder; on standard output,
		 * whose folder is unknown, by its absolute path */
		const char *slash = strrchr(out, '/');
		char *dir = xstrdup(slash ? out : "");
		if (slash)
			dir[slash - out == 0 ? 1 : slash - out] = '\0';
		char version[64], clock[32];
		snprintf(version, sizeof version, "scn %s", PACKAGE_VERSION);
		/* the header's "the POV-Ray 3.7 equivalent of SOURCE" says which moment it is;
		 * POV-Ray's own clock plays no part, as the scene is evaluated here */
		anim_clock_text(at.clock, clock, sizeof clock);
		const char *name = strcmp(scene, "-") == 0 ? "standard input" : scene;
		size_t size = strlen(name) + sizeof " at clock " + sizeof clock;
		char *source = xmalloc(size);
		snprintf(source, size, "%s%s%s", name, clock_given ? " at clock " : "", clock_given ? clock : "");
		struct pov_export_options po = {
			.pov_name = slash ? slash + 1 : out,
			.source = source,
			.generator = version,
			.sky_image = desc.skybox.kind == SKY_IMAGE ? desc.skybox.image_path : NULL,
			.pov_dir = to_stdout ? NULL : dir,
			.look_at = desc.camera.look_at,
			.up = desc.camera.up,
			.fov = desc.camera.fov,
			.sky_rotate = &desc.skybox.rotate,
		};
		char err[1024];
		int e = to_stdout ? pov_export(&sc, &po, stdout, err, sizeof err)
		                  : pov_export_file(&sc, &po, out, err, sizeof err);
		if (e != 0) {
			fprintf(stderr, "scn: %s\n", err);
			rc = EXIT_IO;
		}
		free(source);
		free(dir);
	}
	scene_free(&sc);
	scene_desc_free(&desc);
	diag_fini(&d);
	free(out);
	return rc;
}

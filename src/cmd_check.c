/* cmd_check.c: scn check: parse, check and evaluate a scene; report; optionally dump it. */
#include "config.h"

#include <stdio.h>

#include "cli.h"
#include "diag.h"
#include "load.h"
#include "lower.h"
#include "mesh_dump.h"
#include "scene_desc.h"

enum { OPT_DUMP, NOPTIONS };
static const struct cli_option options[NOPTIONS] = {
	[OPT_DUMP] = { "dump", 0, false },
};

int cmd_check(const struct command *self, int argc, char **argv)
{
	bool dump = false;
	struct cli_parser p;
	cli_parser_init(&p, self, options, NOPTIONS, argc, argv);
	int o;
	while ((o = cli_next_option(&p)) >= 0)
		dump = true; /* OPT_DUMP, the only one */
	if (o == CLI_STOP)
		return p.status < 0 ? 0 : p.status;
	const char *scene = cli_scene(&p);
	if (!scene)
		return EXIT_USAGE;
	struct diag d;
	diag_init(&d, stderr);
	struct scene_desc desc;
	enum load_status status = load_scene(&d, scene, NULL, &desc, NULL);
	/* lowering reads the mesh files and sky images, so that check finds malformed ones */
	struct scene sc = { 0 };
	struct lower_times times;
	if (status == LOAD_OK)
		status = lower_scene(&d, &desc, &sc, &times, -1);
	diag_flush(&d);
	if (status == LOAD_OK && dump) {
		scene_desc_dump(&desc, stdout);
		status = mesh_dump_materials(&desc, stdout);
	}
	scene_free(&sc);
	scene_desc_free(&desc);
	diag_fini(&d);
	return (int)status;
}

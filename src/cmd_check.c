/* cmd_check.c: scn check: parse, check and evaluate a scene; report; optionally dump it. */
#include "config.h"

#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "diag.h"
#include "load.h"
#include "lower.h"
#include "scene_desc.h"

int cmd_check(const struct command *self, int argc, char **argv)
{
	bool dump = false;
	const char *scene = NULL;
	for (int i = 1; i < argc; i++) {
		int taken = cli_scene_arg(self, argv[i], &scene);
		if (taken < 0)
			return EXIT_USAGE;
		if (taken)
			continue;
		if (strcmp(argv[i], "--dump") == 0)
			dump = true;
		else if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0)
			return cli_help(self);
		else
			return cli_usage_error(self, "unknown option '%s' for check", argv[i]);
	}
	if (!scene)
		return cli_usage_error(self, "no scene given");
	struct diag d;
	diag_init(&d, stderr);
	struct scene_desc desc;
	enum load_status status = load_scene(&d, scene, &desc, NULL);
	/* lowering reads the mesh files and sky images, so that check finds malformed ones */
	struct scene sc = { 0 };
	struct lower_times times;
	if (status == LOAD_OK)
		status = lower_scene(&d, &desc, &sc, &times, -1);
	diag_flush(&d);
	if (status == LOAD_OK && dump)
		scene_desc_dump(&desc, stdout);
	scene_free(&sc);
	scene_desc_free(&desc);
	diag_fini(&d);
	return (int)status;
}

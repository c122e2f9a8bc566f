/* main.c: the scn command: argument parsing, dispatch to the subcommands, exit statuses
 * (0 success, 1 errors in the scene, 2 bad command line, 3 a file could not be read or
 * written, 4 the render failed). */
#include "config.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag.h"
#include "load.h"
#include "scene_desc.h"

enum { EXIT_SCENE = 1, EXIT_USAGE = 2, EXIT_IO = 3, EXIT_RENDER = 4 };

struct command {
	const char *name;
	const char *usage;
	const char *help;
	int (*run)(int argc, char **argv);
};

static int run_check(int argc, char **argv);
static int run_not_built(int argc, char **argv);

static const struct command commands[] = {
	{ "check", "scn check [--dump] SCENE",
	  "Parses and checks SCENE ('-' reads standard input) with its includes, and reports\n"
	  "every error and warning as file:line:col with the source line and a caret.\n"
	  "  --dump   print the evaluated scene (every value computed, loops expanded)\n"
	  "Exit status: 0 clean (warnings allowed), 1 errors in the scene, 3 unreadable file.\n",
	  run_check },
	{ "render", "scn render SCENE [-o OUT] [-W WIDTH] [-H HEIGHT] [-s SAMPLES] [-p PATTERN] ...",
	  "Renders SCENE to an image. Not built yet in this version: use 'scn check'.\n",
	  run_not_built },
	{ "pov", "scn pov SCENE [-o OUT.pov]",
	  "Writes the equivalent POV-Ray 3.7 scene. Not built yet in this version.\n",
	  run_not_built },
	{ "diff", "scn diff A B [--heatmap OUT.png] [--max-rmse X]",
	  "Measures the error between two images. Not built yet in this version.\n",
	  run_not_built },
	{ "converge", "scn converge SCENE [--reference REF] [--budget SECONDS] [--csv OUT.csv] [--plot OUT.svg]",
	  "Reports image error against render time. Not built yet in this version.\n",
	  run_not_built },
};
enum { NCOMMANDS = sizeof commands / sizeof commands[0] };

static const struct command *current;

static const struct command *find_command(const char *name)
{
	for (int i = 0; i < NCOMMANDS; i++)
		if (strcmp(commands[i].name, name) == 0)
			return &commands[i];
	return NULL;
}

static void print_usage(FILE *out)
{
	fprintf(out, "usage: scn COMMAND [ARGS]\n\ncommands:\n");
	for (int i = 0; i < NCOMMANDS; i++)
		fprintf(out, "  %s\n", commands[i].usage);
	fprintf(out, "  scn --help | --version | help COMMAND\n");
}

static int usage_error(const char *fmt, const char *arg)
{
	fprintf(stderr, "scn: ");
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\nusage: %s\n", current ? current->usage : "scn COMMAND [ARGS]; see 'scn --help'");
	return EXIT_USAGE;
}

static int run_check(int argc, char **argv)
{
	bool dump = false;
	const char *scene = NULL;
	for (int i = 1; i < argc; i++) {
		if (strcmp(argv[i], "--dump") == 0)
			dump = true;
		else if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
			printf("usage: %s\n\n%s", current->usage, current->help);
			return 0;
		} else if (argv[i][0] == '-' && argv[i][1] != '\0')
			return usage_error("unknown option '%s' for check", argv[i]);
		else if (scene)
			return usage_error("more than one scene given ('%s')", argv[i]);
		else
			scene = argv[i];
	}
	if (!scene)
		return usage_error("no scene given%s", "");
	struct diag d;
	diag_init(&d, stderr);
	struct scene_desc desc;
	enum load_status status = lang_load_scene(&d, scene, &desc);
	if (status == LOAD_OK && dump)
		scene_desc_dump(&desc, stdout);
	scene_desc_free(&desc);
	diag_fini(&d);
	return (int)status;
}

static int run_not_built(int argc, char **argv)
{
	(void)argc;
	(void)argv;
	fprintf(stderr, "scn: '%s' is not built yet in scn %s; 'scn check' parses and checks a scene\n",
	        current->name, PACKAGE_VERSION);
	return EXIT_RENDER;
}

int main(int argc, char **argv)
{
	if (argc < 2) {
		print_usage(stderr);
		return EXIT_USAGE;
	}
	const char *cmd = argv[1];
	if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0) {
		printf("scn %s: a scene description language and Whitted ray tracer\n\n", PACKAGE_VERSION);
		print_usage(stdout);
		printf("\n'scn help COMMAND' describes one command; 'man scn' describes the language.\n");
		return 0;
	}
	if (strcmp(cmd, "--version") == 0) {
		printf("scn %s\n", PACKAGE_VERSION);
		return 0;
	}
	if (strcmp(cmd, "help") == 0) {
		if (argc < 3) {
			print_usage(stdout);
			return 0;
		}
		const struct command *c = find_command(argv[2]);
		if (!c)
			return usage_error("no command '%s'; see 'scn --help'", argv[2]);
		printf("usage: %s\n\n%s", c->usage, c->help);
		return 0;
	}
	current = find_command(cmd);
	if (!current)
		return usage_error("unknown command '%s'; see 'scn --help'", cmd);
	return current->run(argc - 1, argv + 1);
}

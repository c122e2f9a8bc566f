/* cli.h: what the subcommands of scn share: exit statuses, the command table entry,
 * usage errors and option values. */
#ifndef SCN_CLI_H
#define SCN_CLI_H

#include <stdbool.h>
#include <stdint.h>

enum { EXIT_SCENE = 1, EXIT_USAGE = 2, EXIT_IO = 3, EXIT_RENDER = 4 };

struct command {
	const char *name;
	const char *usage;
	const char *help;
	int (*run)(const struct command *self, int argc, char **argv);
};

/* Prints "scn: MESSAGE" and the command's usage line; returns EXIT_USAGE. */
int cli_usage_error(const struct command *cmd, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Prints the command's usage and help to standard output; returns 0. */
int cli_help(const struct command *cmd);
/* The scene argument: when arg is not an option ('-' alone is standard input), takes it
 * into *scene and returns 1, or returns -1 after a usage message when a scene was given
 * already. Returns 0 for an option, which the caller handles. */
int cli_scene_arg(const struct command *cmd, const char *arg, const char **scene);
/* The value of option argv[*i] (the next argument), advancing *i; NULL when missing. */
const char *cli_value(int argc, char **argv, int *i);
/* The name of a scene's output in the current directory: its name with ext (".png"),
 * "stdin" + ext for standard input; malloc'd. */
char *cli_default_output(const char *scene, const char *ext);
/* A whole number in [lo, hi] spelt exactly by s. */
bool cli_int(const char *s, long lo, long hi, long *out);

/* The exit status for a failed read or write with errno e: EXIT_RENDER when memory ran
 * out (ENOMEM), as for any allocation, EXIT_IO otherwise. */
int cli_file_status(int e);

struct diag;
struct span;
/* Whether bytes, for what ("a 640 x 480 image"), fit the machine's memory (memory.h).
 * If not, says so as an error at the scene's place at or, with at NULL, naming the
 * command line's options, and returns EXIT_RENDER; else returns 0. */
int cli_memory_fits(struct diag *d, const struct span *at, const char *options, const char *what, uint64_t bytes);

int cmd_check(const struct command *self, int argc, char **argv);
int cmd_render(const struct command *self, int argc, char **argv);
int cmd_pov(const struct command *self, int argc, char **argv);
int cmd_diff(const struct command *self, int argc, char **argv);
int cmd_converge(const struct command *self, int argc, char **argv);

#endif

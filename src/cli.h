/* cli.h: what the subcommands of scn share: exit statuses, the command table entry,
 * option parsing, usage errors and option values. */
#ifndef SCN_CLI_H
#define SCN_CLI_H

#include <getopt.h>
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
/* An option of a subcommand: its long name without "--" and its letter, either of them
 * absent (NULL, 0), and whether it takes a value. -h and --help come with every table. */
struct cli_option {
	const char *name;
	char letter;
	bool value;
};

enum { CLI_MAX_OPTIONS = 24 };

/* One pass of getopt_long over a subcommand's arguments against its option table. */
struct cli_parser {
	const struct command *cmd;
	const struct cli_option *opts;
	int nopts, argc;
	char **argv;
	char shorts[3 * CLI_MAX_OPTIONS + 3];       /* getopt_long's short options */
	struct option longs[CLI_MAX_OPTIONS + 2];   /* its long ones, --help and the end */
	const char *value;                          /* the value of the option just returned */
	char name[40];                              /* that option as written: "-W", "--seed" */
	int status;                                 /* after CLI_STOP: EXIT_USAGE, or -1: help shown */
};

enum { CLI_END = -1, CLI_STOP = -2 };

/* Starts parsing argv[1 .. argc) against the nopts options of opts (at most
 * CLI_MAX_OPTIONS), with GNU's conventions: --name=value or --name value, long names
 * abbreviated to any unique prefix, -sVALUE or -s VALUE, bundled letters (-qj2),
 * operands among the options, and '--' ending the options. */
void cli_parser_init(struct cli_parser *p, const struct command *cmd, const struct cli_option *opts, int nopts,
                     int argc, char **argv);
/* The index in opts of the next option, its value in p->value and its spelling in
 * p->name; CLI_END after the last one, or CLI_STOP once the help is shown or a usage
 * error for an unknown, ambiguous or ill-valued option is reported (p->status). */
int cli_next_option(struct cli_parser *p);
/* The operands after the options, *n of them, once cli_next_option returned CLI_END;
 * NULL after a usage message for one that starts with '+' and names no file: a POV-Ray
 * option, as +W320, with scn's equivalent when the command has one (pov_hint.h). */
char **cli_operands(struct cli_parser *p, int *n);
/* The one scene operand ('-' is standard input), or NULL after a usage message: no
 * scene, more than one, or a POV-Ray option (cli_operands). */
const char *cli_scene(struct cli_parser *p);
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
int cmd_merge(const struct command *self, int argc, char **argv);

#endif

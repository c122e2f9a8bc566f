/* main.c: the scn command: dispatch to the subcommands, --help and --version. Exit
 * statuses: 0 success, 1 errors in the scene, 2 bad command line, 3 a file could not be
 * read or written, 4 the render failed (out of memory), 128 + N killed by signal N (after
 * removing its temporary files: cleanup.h). */
#include "config.h"

#include <stdio.h>
#include <string.h>

#include "cleanup.h"
#include "cli.h"

static const struct command commands[] = {
	{ "check", "scn check [--dump] SCENE",
	  "Parses and checks SCENE ('-' reads standard input) with its includes, and reports\n"
	  "every error and warning as file:line:col with the source line and a caret.\n"
	  "  --dump   print the evaluated scene (every value computed, loops expanded)\n"
	  "Exit status: 0 clean (warnings allowed), 1 errors in the scene, 3 unreadable file.\n",
	  cmd_check },
	{ "render",
	  "scn render SCENE [-o OUT] [-W WIDTH] [-H HEIGHT] [-s SAMPLES] [-p PATTERN] [-d MAX_DEPTH]\n"
	  "                  [-j THREADS] [--accel bvh|grid|none] [--region X0,Y0,X1,Y1] [--seed N]\n"
	  "                  [--bit-depth 8|16] [--float] [--stats] [--progress | --no-progress] [-q]\n"
	  "                  [--clock C | --frames A..B [--cyclic]] [--tile K/N]",
	  "Renders SCENE ('-' reads standard input) to OUT, by default the scene's name with .png.\n"
	  "OUT's extension picks the format: .png (8-bit sRGB, or --bit-depth 16), .exr (linear\n"
	  "half float, or --float for 32-bit), .ppm (sRGB, 8 or 16 bits). The image is written to a\n"
	  "temporary file and renamed into place, so a failed render leaves no partial file.\n"
	  "  -W, -H        image size, overriding the camera's resolution\n"
	  "  -s, -p        samples per pixel and their pattern (center grid random jittered poisson)\n"
	  "  -d            max_depth, the bounce limit\n"
	  "  -j            threads; 0 (the default) uses every core; the image does not depend on it\n"
	  "  --accel       bvh (the default), grid (uniform grid) or none (brute force)\n"
	  "  --region      render only the pixels [X0,X1) x [Y0,Y1); the image is that rectangle\n"
	  "  --seed        the sampling seed\n"
	  "  --stats       time of each phase, rays by kind, non-finite radiance values\n"
	  "  --progress    a progress bar with an ETA on standard error (default: on a terminal)\n"
	  "  -q            no progress bar\n"
	  "  --clock C     the scene's clock is C (its frame is 0)\n"
	  "  --frames A..B renders frames A, A+1, ..., B-1, each a whole evaluation of the scene\n"
	  "                with frame its number and clock going from 0 at A to 1 at B-1\n"
	  "  --cyclic      with --frames: clock (frame - A) / (B - A), so B-1 leads back to A\n"
	  "  --tile K/N    renders part K (from 0) of the image split into N bands of rows, part K\n"
	  "                the rows [floor(K*H/N), floor((K+1)*H/N)) of the image (or of --region's\n"
	  "                rectangle), as a 32-bit float OpenEXR file (default: SCENE-K-of-N.exr)\n"
	  "                that places it in the whole and names the scene and settings; 'scn merge'\n"
	  "                joins the parts into the image a render of the whole would write\n"
	  "With --frames, OUT's %d or %0Nd (one; %% is a '%') is the frame's number; without\n"
	  "one, the number goes before the extension, padded with zeros to the digits of B-1\n"
	  "(anim.png, --frames 1..25: anim01.png ... anim24.png). The first frame's warnings are\n"
	  "shown, a later frame's diagnostics only when it fails; a failure names its frame and\n"
	  "ends the run. --progress counts frames, --stats is per frame. SCENE is read for each\n"
	  "frame, so it cannot be '-'. --tile renders one image: render one frame per task instead.\n"
	  "Under an MPI launcher (mpirun -np N scn render ...), the processes share the image's\n"
	  "tiles, or whole frames, and process 0 writes the same bytes as one process ('man scn', MPI).\n"
	  "Exit status: 0 success, 1 errors in the scene, 2 bad command line, 3 a file could not\n"
	  "be read or written, 4 the render failed.\n",
	  cmd_render },
	{ "merge", "scn merge PART.exr ... -o OUT [--bit-depth 8|16] [--float] [-q]",
	  "Joins the parts that 'scn render --tile K/N' wrote, given in any order, into OUT (.png,\n"
	  ".exr or .ppm, as for scn render), which has the bytes that one render of the whole image\n"
	  "with the same options writes. Each part must be one, from the same scn version, scene\n"
	  "(the scene after the command line's overrides and the files it reads), settings and split\n"
	  "N, and every part 0 .. N-1 must be there once; otherwise nothing is written. Prints the\n"
	  "size, the number of parts and the error estimate of the whole, as scn render does.\n"
	  "  -o OUT        the image to write (required)\n"
	  "  --bit-depth   8 or 16 bits per channel for PNG and PPM\n"
	  "  --float       32-bit float EXR instead of half\n"
	  "  -q            no 'wrote' line\n"
	  "Exit status: 0 success, 2 bad command line, 3 a part could not be read, is not a part,\n"
	  "or the parts do not make one image, or OUT could not be written, 4 out of memory.\n",
	  cmd_merge },
	{ "pov", "scn pov SCENE [-o OUT.pov] [--clock C]",
	  "Writes the POV-Ray 3.7 scene that renders the same image as SCENE ('-' reads standard\n"
	  "input) to OUT.pov, by default the scene's name with .pov ('-o -': standard output).\n"
	  "Its third line, '// Render: povray ...', is the command that renders it, run in the\n"
	  "file's folder, into NAME-pov.png (a 16-bit linear PNG; NAME.png is scn render's); the\n"
	  "comments after it say what POV-Ray cannot match exactly, such as random sample\n"
	  "patterns. The file is written to a temporary file and renamed into place.\n"
	  "  --clock C   evaluates the scene with clock C (frame 0): one frame of an animation,\n"
	  "              which the header names (\"the equivalent of SCENE at clock C\")\n"
	  "Exit status: 0 success, 1 errors in the scene, 2 bad command line, 3 a file could not\n"
	  "be read or written.\n",
	  cmd_pov },
	{ "diff",
	  "scn diff A B [--heatmap OUT.png] [--downsample N] [--ppm srgb|linear[,srgb|linear]]\n"
	  "              [--max-rmse X] [--min-psnr DB] [--max-error X] [--max-mean X] [--max-off P%] [-q]",
	  "Compares images A and B (PNG 8 or 16 bits, OpenEXR, binary PPM) in linear light: every\n"
	  "channel of every pixel. A PNG follows its sRGB and gAMA chunks (POV-Ray's +FN16\n"
	  "File_Gamma=1.0 files say gAMA 1.0: linear) and is sRGB without them; EXR is linear; PPM,\n"
	  "which cannot say, is taken as sRGB (scn's and POV-Ray's default) unless --ppm says linear\n"
	  "(POV-Ray with File_Gamma=1.0). Prints one line per metric:\n"
	  "  size WxH\n"
	  "  rmse R (psnr P dB)       root mean square channel error; psnr = 20 log10(1/R), inf if R = 0\n"
	  "  mean M                   mean absolute channel error\n"
	  "  bias B                   mean signed channel error A - B: one image brighter than the\n"
	  "                           other, where noise alone averages out\n"
	  "  max E at (X, Y)          largest channel error and its first pixel, row 0 at the top\n"
	  "                           (without 'at' when E is 0)\n"
	  "  off>1/255 S% (N pixels)  pixels with a channel off by more than 1/255\n"
	  "  off>2/255 S% (N pixels)  the same for 2/255\n"
	  "  --heatmap OUT   a false-colour image (.png, .exr or .ppm) of each pixel's largest\n"
	  "                  channel error on a log scale: black below 2^-17, then dark blue at\n"
	  "                  1/65535, blue at 2^-12, yellow at 1/256, white at 1/16 and above\n"
	  "  --downsample N  average B over N x N blocks first (B is N times A's size)\n"
	  "  --ppm ENC       how PPM samples are encoded: srgb (default) or linear, for both\n"
	  "                  images, or A's,B's (e.g. srgb,linear)\n"
	  "  --max-rmse X  --min-psnr DB  --max-error X  --max-mean X\n"
	  "                  fail when the metric is beyond X (X may be a fraction: 2/65535)\n"
	  "  --max-off P%    fail when more than P% of the pixels are off by more than 2/255\n"
	  "  -q              print no metrics, only the failures\n"
	  "Exit status: 0 compared and within every limit, 1 a limit is exceeded (each is named\n"
	  "on standard error) or the sizes differ, 2 bad command line, 3 an image could not be\n"
	  "read or the heatmap written, 4 an image needs more memory than the machine has.\n",
	  cmd_diff },
	{ "converge",
	  "scn converge SCENE [--reference REF] [--budget SECONDS] [--csv OUT.csv] [--plot OUT.svg]\n"
	  "                    [-j THREADS] [-W WIDTH] [-H HEIGHT] [--reference-samples N] [--no-pov] [-q]",
	  "Error against run time. Loads SCENE once and renders it at rising sample counts (1, 4,\n"
	  "16, ...) for the patterns random, jittered, poisson and grid, and adaptively (jittered,\n"
	  "target_error 0.02, 0.01, ...); POV-Ray renders the scene's twin (scn pov) with -A, then\n"
	  "+A0.0 +AM2 +R1, +R2, ... -J. A scene with area lights gives POV-Ray one more series per\n"
	  "area_light adaptive level below its full subdivision (\"POV-Ray adaptive 0\", 1, ...;\n"
	  "an 8 x 8 light has two), \"POV-Ray\" being the twin without adaptive. Each image is\n"
	  "compared with one reference, clipped to [0, 1]. The points run cheapest first while\n"
	  "they fit in the budget. Prints a table (series, setting, samples per pixel, seconds,\n"
	  "RMSE, estimated RMSE); its last line is the ratio of scn's time to POV-Ray's at the\n"
	  "lowest RMSE both reach (with several POV-Ray series, that every one reaches), for scn's\n"
	  "fastest series there and POV-Ray's fastest (named when it has several). scn's seconds\n"
	  "are its render alone (its load, lower and BVH time is printed once and added for the\n"
	  "ratio); POV-Ray's are its whole process, start-up included.\n"
	  "  --reference REF  the reference image (PNG, EXR, PPM); by default a grid render with\n"
	  "                   64 x 64, 32 x 32 or 16 x 16 samples, the most that takes at most half\n"
	  "                   the budget; the series go up to a 16th of its count\n"
	  "  --reference-samples N  the default reference's count instead (a square, 16 or more)\n"
	  "  --budget S       seconds for everything, 120 by default\n"
	  "  --csv OUT.csv    the table as CSV\n"
	  "  --plot OUT.svg   RMSE against seconds, log-log, one line per series\n"
	  "  -j               threads for scn and POV-Ray (+WT); 0 (the default): every core\n"
	  "  -W, -H           the image size (one alone keeps the scene's aspect ratio)\n"
	  "  --no-pov         no POV-Ray series (also when povray is not on PATH)\n"
	  "  -q               no progress lines on standard error\n"
	  "Exit status: 0 success, 1 errors in the scene, 2 bad command line, 3 a file could not\n"
	  "be read or written, 4 the render failed.\n",
	  cmd_converge },
};
enum { NCOMMANDS = sizeof commands / sizeof commands[0] };

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
	fprintf(out, "  scn --help | --version | help COMMAND\n\n");
	fprintf(out, "Options may come before or after the operands, in GNU's forms: --seed=5 or --seed 5,\n"
	             "--se 5 (any unique prefix), -s16 or -s 16, -qj2 for -q -j 2; '--' ends the options.\n"
	             "POV-Ray's options (+W320) are not scn's; the error names the command's equivalent.\n");
}

int main(int argc, char **argv)
{
	cleanup_install_signals();
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
		return c ? cli_help(c) : cli_usage_error(NULL, "no command '%s'; see 'scn --help'", argv[2]);
	}
	const struct command *c = find_command(cmd);
	if (!c)
		return cli_usage_error(NULL, "unknown command '%s'; see 'scn --help'", cmd);
	return c->run(c, argc - 1, argv + 1);
}

/* options.h: the command line and .ini files. lucent takes POV-Ray's
 * switches (+W640, -V, +Ofile.png, ...), .ini files named on the command
 * line (Key=Value with POV-Ray's key names), and GNU long options. */
#ifndef LUCENT_OPTIONS_H
#define LUCENT_OPTIONS_H

#include "image/output.h"
#include "lang/parse.h"

#include <stdbool.h>
#include <stdio.h>

struct options {
	char *input;            /* scene file; "-" for standard input */
	char *output;           /* output file; NULL: derived from input */
	bool output_to_file;    /* -F turns file output off */
	int width, height;
	enum img_format format;
	bool format_set;        /* +F given: overrides the output's extension */
	int bits;               /* 8 or 16 */
	bool alpha;             /* +UA */
	bool tga_rle;           /* +FC: run-length encoded TGA (+FT: uncompressed) */
	char **lib_paths;       /* +L, in order */
	size_t nlib_paths;
	int threads;            /* 0: one per core */
	int verbose;            /* +V: 1 */
	bool quiet;             /* -q: only #debug/#warning text and errors */
	char *debug_file;       /* +GDfile: #debug text goes to this file */
	bool io_unrestricted;   /* --io-unrestricted: #fopen may use any path */
	struct parse_limits limits; /* --limit NAME=N (0: the default) */
	double max_image;       /* --limit image-size=N: most pixels in the image */
	bool signature;         /* --signature: flat colour per object, no shading */
	struct parse_define *defines;
	size_t ndefines;
	double start_row, end_row, start_col, end_col; /* as given; < 0: unset */
	double clock;
	/* Antialiasing and quality (POV-Ray's +A, +AM, +R, +J, +AG, +Q). */
	bool antialias;         /* +A */
	double aa_threshold;    /* +A0.3: colour difference that supersamples */
	int aa_method;          /* +AM: 1 non-recursive, 2 recursive */
	int aa_depth;           /* +R: 1 to 9 */
	bool jitter;            /* +J */
	double jitter_amount;   /* +J1.0: 0 to 1 of a sub-sample cell */
	double aa_gamma;        /* +AG2.5: gamma of the colour comparison */
	int quality;            /* +Q: 0 to 11 */
	bool help, version;
};

void options_init(struct options *o);
void options_free(struct options *o);
/* Parse argv into o, reading .ini files it names. Messages go to err.
 * Returns 0 on success, 1 on a bad option (already reported). */
int options_parse(struct options *o, int argc, char **argv, FILE *err);
/* Resolve a partial-render bound (POV-Ray's rule: 0 < v <= 1 is a fraction
 * of size, otherwise a 1-based pixel number) to a 0-based index.
 * For an end bound the result is exclusive. */
int options_bound(double v, int size, bool is_end);
/* Print the --help text. */
void options_usage(FILE *out);

#endif

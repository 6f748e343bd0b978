/* options.c: command line and .ini parsing (see options.h). */
#include "options.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

void options_init(struct options *o)
{
	memset(o, 0, sizeof *o);
	o->output_to_file = true;
	o->width = 800;
	o->height = 600;
	o->max_image = 1e8;
	o->format = IMG_PNG;
	o->bits = 8;
	o->start_row = o->end_row = o->start_col = o->end_col = -1;
	/* POV-Ray 3.7's defaults (its option listing with +A alone). */
	o->aa_threshold = 0.3;
	o->aa_method = 1;
	o->aa_depth = 3;
	o->jitter = true;
	o->jitter_amount = 1.0;
	o->aa_gamma = 2.5;
	o->quality = 9;
}

void options_free(struct options *o)
{
	free(o->input);
	free(o->output);
	free(o->debug_file);
	for (size_t i = 0; i < o->nlib_paths; i++)
		free(o->lib_paths[i]);
	free(o->lib_paths);
	for (size_t i = 0; i < o->ndefines; i++)
		free((char *)o->defines[i].name);
	free(o->defines);
}

void options_usage(FILE *out)
{
	fputs(
"usage: lucent [options] scene.pov\n"
"       lucent [+I]scene.pov [+Oout.png] [+W640 +H480] [file.ini] ...\n"
"\n"
"Renders a POV-Ray scene. Switches use POV-Ray's syntax: +X turns on or\n"
"sets X, -X turns it off; values are glued on (+W640).\n"
"\n"
"  +Ifile, file   scene to render ('-' reads standard input)\n"
"  +Ofile         output image (default: the scene's name with the format's\n"
"                 extension); -F writes no file\n"
"  +Wn, +Hn       image width and height (default 800x600)\n"
"  +F[type][bits] output format: N png, N16 16-bit png, E exr, H hdr,\n"
"                 T tga, C compressed tga, P ppm (P16: 16-bit), J jpeg;\n"
"                 TIFF by the .tif extension\n"
"  +UA            write an alpha channel (background transparent)\n"
"  +Lpath         add an include library folder (repeatable)\n"
"  +WTn           render threads (default: one per core)\n"
"  +SRn +ERn      start/end row; +SCn +ECn start/end column (a pixel\n"
"                 number, or a fraction of the size if between 0 and 1)\n"
"  +A[t], -A      antialiasing on (colour difference t, default 0.3) or off\n"
"  +AMn           antialiasing method: 1 adaptive, 2 recursive adaptive\n"
"  +Rn            antialiasing depth 1 to 9 (method 1: n x n samples;\n"
"                 method 2: n-1 subdivisions); default 3\n"
"  +J[a], -J      jitter the samples (amount a from 0 to 1, default 1)\n"
"  +AGg           gamma of the antialiasing colour comparison (default 2.5)\n"
"  +Qn            quality 0 to 11 (default 9): lower levels leave out effects\n"
"  +V, -V         verbose output on or off\n"
"  Declare=N=V    declare identifier N as the float V\n"
"  +GDfile        write #debug text to file instead of the console\n"
"  file.ini       read switches and Key=Value options from an .ini file\n"
"\n"
"  -q, --quiet    print only #debug/#warning text and errors\n"
"  --io-unrestricted  let the scene read and write outside its folder\n"
"                 (and the +L paths and the stdlib, which it may read)\n"
"  --limit NAME=N raise a bound: macro-depth (1000), include-depth (100),\n"
"                 expr-depth (256), csg-depth (1000), array-size (1e8),\n"
"                 string-length (2^28), mesh-size (1e8), image-size (1e8 pixels)\n"
"  --signature    flat colour per object, no lighting (checks intersection)\n"
"  --threads N    as +WTN\n"
"  --output FILE  as +OFILE\n"
"  --regress ARGS run lucent-regress ARGS: render and check a scene corpus\n"
"  -h, --help     show this help\n"
"  --version      show the version\n"
"\n"
"Exit status: 0 done, 1 error, 2 interrupted.\n"
"See lucent(1) and doc/ in the source tree for the full reference.\n", out);
}

static char *xstrdup(const char *s)
{
	char *c = strdup(s);
	if (!c) abort();
	return c;
}

static void set_str(char **dst, const char *s)
{
	free(*dst);
	*dst = xstrdup(s);
}

/* Parse a whole number or a float; false if s is not one. */
static bool parse_num(const char *s, double *v)
{
	if (!*s)
		return false;
	char *end;
	errno = 0;
	*v = strtod(s, &end);
	return *end == 0 && errno == 0 && isfinite(*v);
}

static bool parse_bool(const char *s, bool *b)
{
	static const char *const yes[] = {"on", "true", "yes", "1"};
	static const char *const no[] = {"off", "false", "no", "0"};
	for (int i = 0; i < 4; i++) {
		if (strcasecmp(s, yes[i]) == 0) { *b = true; return true; }
		if (strcasecmp(s, no[i]) == 0) { *b = false; return true; }
	}
	return false;
}

/* Where a setting came from, for messages. */
struct origin {
	const char *file; /* NULL: the command line */
	int line;
};

static void report(FILE *err, const struct origin *at, const char *level, const char *fmt, const char *arg)
{
	if (at->file)
		fprintf(err, "%s:%d: %s: ", at->file, at->line, level);
	else
		fprintf(err, "lucent: %s: ", level);
	fprintf(err, fmt, arg);
	fputc('\n', err);
}

static int add_define(struct options *o, const char *spec, FILE *err, const struct origin *at)
{
	const char *eq = strchr(spec, '=');
	double v;
	if (!eq || eq == spec || !parse_num(eq + 1, &v)) {
		report(err, at, "error", "Declare wants NAME=FLOAT, not '%s'", spec);
		return 1;
	}
	for (const char *c = spec; c < eq; c++)
		if (!(isalnum((unsigned char)*c) || *c == '_') || (c == spec && isdigit((unsigned char)*c))) {
			report(err, at, "error", "Declare: '%s' does not start with a valid identifier", spec);
			return 1;
		}
	o->defines = realloc(o->defines, (o->ndefines + 1) * sizeof *o->defines);
	if (!o->defines) abort();
	char *name = strndup(spec, (size_t)(eq - spec));
	if (!name) abort();
	o->defines[o->ndefines].name = name;
	o->defines[o->ndefines].value = v;
	o->ndefines++;
	return 0;
}

static void add_lib(struct options *o, const char *path)
{
	o->lib_paths = realloc(o->lib_paths, (o->nlib_paths + 1) * sizeof *o->lib_paths);
	if (!o->lib_paths) abort();
	o->lib_paths[o->nlib_paths++] = xstrdup(path);
}

/* +F argument: [type letter][bits]. */
static int set_format(struct options *o, const char *arg, FILE *err, const struct origin *at)
{
	if (!*arg)
		return 0; /* +F alone: file output on, default format */
	char c = (char)toupper((unsigned char)arg[0]);
	static const struct { char c; enum img_format f; } map[] = {
		{'N', IMG_PNG}, {'E', IMG_EXR}, {'H', IMG_HDR}, {'T', IMG_TGA}, {'C', IMG_TGA},
		{'P', IMG_PPM}, {'J', IMG_JPEG},
	};
	size_t i;
	for (i = 0; i < sizeof map / sizeof map[0]; i++)
		if (map[i].c == c)
			break;
	if (i == sizeof map / sizeof map[0]) {
		report(err, at, "error", "unknown output format in '+F%s' (N, E, H, T, C, P or J)", arg);
		return 1;
	}
	o->format = map[i].f;
	o->format_set = true;
	o->tga_rle = c == 'C';
	if (arg[1]) {
		double b;
		if (!parse_num(arg + 1, &b) || (b != 8 && b != 16)) {
			report(err, at, "error", "bits per colour in '+F%s' must be 8 or 16", arg);
			return 1;
		}
		o->bits = (int)b;
	}
	return 0;
}

/* POV-Ray switches lucent knows of but does not implement yet, with what
 * they do, so the warning can say it. Longest prefixes first. */
static const struct { const char *sw; const char *what; } unimplemented[] = {
	{"RTR", "real-time raytracing"}, {"RVP", "real-time viewport"}, {"RS", "radiosity"},
	{"BM", "bounding method"}, {"BS", "block size"},
	{"KFI", "initial animation frame"}, {"KFF", "final animation frame"}, {"KI", "initial clock"},
	{"KF", "final clock"}, {"KC", "cyclic animation"},
	{"MB", "bounding threshold"}, {"MV", "language version"}, {"UR", "remove bounds"},
	{"UO", "bounding order"}, {"UD", "draw vistas"}, {"UF", "field render"},
	{"UL", "light buffer"}, {"UV", "vista buffer"}, {"SF", "start frame"}, {"EF", "end frame"},
	{"X", "abort on key"}, {"P", "pause when done"}, {"C", "continue an interrupted render"},
	{"B", "output buffer"}, {"HI", "header include"}, {"GS", "statistics stream"},
	{"GR", "render stream"}, {"GW", "warning stream"},
	{"GF", "fatal stream"}, {"GP", "parse stream"}, {"GI", "ini file log"},
	{"SP", "mosaic preview start"}, {"EP", "mosaic preview end"}, {"TH", "tiling"},
	{"STP", "status update"}, {"HT", "histogram type"}, {"HN", "histogram name"},
	{"HS", "histogram size"},
};

static bool starts_ci(const char *s, const char *prefix)
{
	return strncasecmp(s, prefix, strlen(prefix)) == 0;
}

static int read_ini(struct options *o, const char *path, FILE *err, int depth);

/* One POV-Ray switch without its sign: "W640", "Oout.png". */
static int switch_arg(struct options *o, char sign, const char *s, FILE *err, const struct origin *at)
{
	bool on = sign == '+';
	double v;
	char full[512];
	snprintf(full, sizeof full, "%c%s", sign, s);
#define NUM(off, dst, cond, what)                                                   \
	do {                                                                         \
		if (!parse_num(s + (off), &v) || !(cond)) {                           \
			report(err, at, "error", "bad value in '%s': " what, full);       \
			return 1;                                                        \
		}                                                                    \
		dst;                                                                 \
	} while (0)

	if (starts_ci(s, "WT")) {
		NUM(2, o->threads = (int)v, v >= 1 && v <= 1024 && v == floor(v), "threads must be a whole number from 1 to 1024");
		return 0;
	}
	if (starts_ci(s, "SR")) { NUM(2, o->start_row = v, v >= 0, "must not be negative"); return 0; }
	if (starts_ci(s, "ER")) { NUM(2, o->end_row = v, v >= 0, "must not be negative"); return 0; }
	if (starts_ci(s, "SC")) { NUM(2, o->start_col = v, v >= 0, "must not be negative"); return 0; }
	if (starts_ci(s, "EC")) { NUM(2, o->end_col = v, v >= 0, "must not be negative"); return 0; }
	if (starts_ci(s, "UA") && s[2] == 0) { o->alpha = on; return 0; }
	if (starts_ci(s, "GA") && s[2] == 0) { o->quiet = !on; return 0; }
	if (starts_ci(s, "GD")) {
		/* +GDfile: the debug stream (#debug text) into a file; -GD, +GD: to
		 * the console. */
		if (on && s[2])
			set_str(&o->debug_file, s + 2);
		else {
			free(o->debug_file);
			o->debug_file = NULL;
		}
		return 0;
	}
	if (toupper((unsigned char)s[0]) == 'D' && (s[1] == 0 || isdigit((unsigned char)s[1]) || s[1] == 'G')) {
		/* Preview display: lucent has none; off is what it always does. */
		if (on)
			report(err, at, "warning", "switch '%s' (preview display) is not implemented; rendering to the file only", full);
		return 0;
	}
	/* Antialiasing and quality. A value after -A or -J is kept for a later
	 * +A or +J, as in POV-Ray. */
	if (starts_ci(s, "AM")) {
		NUM(2, o->aa_method = (int)v, v == 1 || v == 2, "the sampling method is 1 or 2");
		return 0;
	}
	if (starts_ci(s, "AG")) {
		NUM(2, o->aa_gamma = v, v > 0 && v <= 10, "the antialiasing gamma must be above 0 and at most 10");
		return 0;
	}
	if (toupper((unsigned char)s[0]) == 'A') {
		if (s[1])
			NUM(1, o->aa_threshold = v, v >= 0 && v <= 3, "the antialiasing threshold must be from 0 to 3");
		o->antialias = on;
		return 0;
	}
	if (toupper((unsigned char)s[0]) == 'R' && (s[1] == 0 || isdigit((unsigned char)s[1]) || s[1] == '.' || s[1] == '-')) {
		NUM(1, o->aa_depth = (int)v, v >= 1 && v <= 9 && v == floor(v), "the antialiasing depth is a whole number from 1 to 9");
		return 0;
	}
	if (toupper((unsigned char)s[0]) == 'J') {
		if (s[1])
			NUM(1, o->jitter_amount = v, v >= 0 && v <= 1, "the jitter amount must be from 0 to 1");
		/* As POV-Ray: an amount of 0 turns jitter off. */
		o->jitter = on && o->jitter_amount > 0;
		return 0;
	}
	if (toupper((unsigned char)s[0]) == 'Q') {
		NUM(1, o->quality = (int)v, v >= 0 && v <= 11 && v == floor(v), "the quality is a whole number from 0 to 11");
		return 0;
	}
	for (size_t i = 0; i < sizeof unimplemented / sizeof unimplemented[0]; i++)
		if (starts_ci(s, unimplemented[i].sw)) {
			if (on) {
				char msg[600];
				snprintf(msg, sizeof msg, "switch '%%s' (%s) is not implemented yet; ignored", unimplemented[i].what);
				report(err, at, "warning", msg, full);
			}
			return 0;
		}
	switch (toupper((unsigned char)s[0])) {
	case 'K':
		NUM(1, o->clock = v, 1, "the clock must be a number");
		return 0;
	case 'W':
		NUM(1, o->width = (int)v, v >= 1 && v <= 65536 && v == floor(v), "width must be a whole number from 1 to 65536");
		return 0;
	case 'H':
		NUM(1, o->height = (int)v, v >= 1 && v <= 65536 && v == floor(v), "height must be a whole number from 1 to 65536");
		return 0;
	case 'I':
		if (!s[1]) { report(err, at, "error", "'%s' needs a file name", full); return 1; }
		set_str(&o->input, s + 1);
		return 0;
	case 'O':
		if (!s[1]) { report(err, at, "error", "'%s' needs a file name", full); return 1; }
		set_str(&o->output, s + 1);
		return 0;
	case 'F':
		o->output_to_file = on;
		return on ? set_format(o, s + 1, err, at) : 0;
	case 'L':
		if (!s[1]) { report(err, at, "error", "'%s' needs a folder", full); return 1; }
		add_lib(o, s + 1);
		return 0;
	case 'V':
		if (s[1]) break;
		o->verbose = on;
		return 0;
	default:
		break;
	}
#undef NUM
	report(err, at, "error", "unknown switch '%s' (see lucent --help)", full);
	return 1;
}

/* Key=Value from an .ini file or the command line. */
static int key_value(struct options *o, const char *key, const char *val, FILE *err, const struct origin *at, int depth)
{
	bool b;
	double v;
	char buf[1024];
	static const struct { const char *key; const char *sw; } as_switch[] = {
		{"Width", "W"}, {"Height", "H"}, {"Start_Row", "SR"}, {"End_Row", "ER"},
		{"Start_Column", "SC"}, {"End_Column", "EC"}, {"Work_Threads", "WT"},
		{"Sampling_Method", "AM"}, {"Antialias_Depth", "R"}, {"Antialias_Gamma", "AG"}, {"Quality", "Q"},
	};
	/* Values that do not turn their feature on: checked as the switch,
	 * which does, and the on/off state put back. */
	static const struct { const char *key; const char *sw; } amounts[] = {
		{"Antialias_Threshold", "A"}, {"Jitter_Amount", "J"},
	};
	for (size_t i = 0; i < sizeof amounts / sizeof amounts[0]; i++)
		if (strcasecmp(key, amounts[i].key) == 0) {
			bool aa = o->antialias, jit = o->jitter;
			if (!*val) {
				report(err, at, "error", "%s needs a value", key);
				return 1;
			}
			snprintf(buf, sizeof buf, "%s%s", amounts[i].sw, val);
			if (switch_arg(o, '+', buf, err, at))
				return 1;
			o->antialias = aa;
			/* Jitter_Amount=0 turns jitter off (POV-Ray's manual). */
			o->jitter = jit && o->jitter_amount > 0;
			return 0;
		}
	for (size_t i = 0; i < sizeof as_switch / sizeof as_switch[0]; i++)
		if (strcasecmp(key, as_switch[i].key) == 0) {
			snprintf(buf, sizeof buf, "%s%s", as_switch[i].sw, val);
			return switch_arg(o, '+', buf, err, at);
		}
	if (strcasecmp(key, "Input_File_Name") == 0) { set_str(&o->input, val); return 0; }
	if (strcasecmp(key, "Output_File_Name") == 0) { set_str(&o->output, val); return 0; }
	if (strcasecmp(key, "Library_Path") == 0) { add_lib(o, val); return 0; }
	if (strcasecmp(key, "Declare") == 0) return add_define(o, val, err, at);
	if (strcasecmp(key, "Output_File_Type") == 0) return set_format(o, val, err, at);
	if (strcasecmp(key, "Bits_Per_Color") == 0 || strcasecmp(key, "Bits_Per_Colour") == 0) {
		if (!parse_num(val, &v) || (v != 8 && v != 16)) {
			report(err, at, "error", "Bits_Per_Color must be 8 or 16, not '%s'", val);
			return 1;
		}
		o->bits = (int)v;
		return 0;
	}
	if (strcasecmp(key, "Clock") == 0) {
		if (!parse_num(val, &v)) { report(err, at, "error", "Clock wants a number, not '%s'", val); return 1; }
		o->clock = v;
		return 0;
	}
	struct { const char *key; bool *dst; bool invert; } bools[] = {
		{"Output_Alpha", &o->alpha, false}, {"Output_to_File", &o->output_to_file, false},
		{"Verbose", NULL, false}, {"Antialias", &o->antialias, false}, {"Jitter", &o->jitter, false},
	};
	for (size_t i = 0; i < sizeof bools / sizeof bools[0]; i++)
		if (strcasecmp(key, bools[i].key) == 0) {
			if (!parse_bool(val, &b)) {
				snprintf(buf, sizeof buf, "%s wants on or off, not '%%s'", key);
				report(err, at, "error", buf, val);
				return 1;
			}
			if (bools[i].dst)
				*bools[i].dst = b;
			else
				o->verbose = b;
			return 0;
		}
	if (strcasecmp(key, "Include_Ini") == 0)
		return read_ini(o, val, err, depth + 1);
	/* POV-Ray keys with no effect in lucent: the preview display and
	 * console streams. */
	static const char *const harmless[] = {"Display", "Pause_When_Done", "Display_Gamma",
		"Debug_Console", "Fatal_Console", "Render_Console", "Statistic_Console", "Warning_Console",
		"Test_Abort", "Test_Abort_Count", "Bounding_Threshold", "Bounding"};
	for (size_t i = 0; i < sizeof harmless / sizeof harmless[0]; i++)
		if (strcasecmp(key, harmless[i]) == 0)
			return 0;
	static const char *const known_unimplemented[] = {"Initial_Frame", "Final_Frame", "Initial_Clock", "Final_Clock", "Cyclic_Animation",
		"Subset_Start_Frame", "Subset_End_Frame", "File_Gamma", "Continue_Trace", "Create_Histogram",
		"Version", "Radiosity_File_Name", "Remove_Bounds", "Split_Unions"};
	for (size_t i = 0; i < sizeof known_unimplemented / sizeof known_unimplemented[0]; i++)
		if (strcasecmp(key, known_unimplemented[i]) == 0) {
			report(err, at, "warning", "option '%s' is not implemented yet; ignored", key);
			return 0;
		}
	report(err, at, "error", "unknown option '%s'", key);
	return 1;
}

static char *trim(char *s)
{
	while (isspace((unsigned char)*s))
		s++;
	char *e = s + strlen(s);
	while (e > s && isspace((unsigned char)e[-1]))
		*--e = 0;
	return s;
}

static int one_arg(struct options *o, const char *a, FILE *err, const struct origin *at, int depth);

/* An .ini file: Key=Value lines, switches, ';' comments, [sections]. */
static int read_ini(struct options *o, const char *path, FILE *err, int depth)
{
	struct origin at = {NULL, 0};
	if (depth > 10) {
		report(err, &at, "error", "ini files include each other too deeply (at '%s')", path);
		return 1;
	}
	at.file = path;
	FILE *f = fopen(path, "r");
	if (!f) {
		fprintf(err, "lucent: error: cannot read ini file '%s': %s\n", path, strerror(errno));
		return 1;
	}
	char line[4096];
	int rc = 0;
	while (!rc && fgets(line, sizeof line, f)) {
		at.line++;
		char *semi = strchr(line, ';');
		if (semi)
			*semi = 0;
		char *s = trim(line);
		if (!*s || *s == '[')
			continue;
		char *eq = strchr(s, '=');
		if (eq && *s != '+' && *s != '-') {
			*eq = 0;
			char *val = trim(eq + 1);
			size_t n = strlen(val);
			if (n >= 2 && val[0] == '"' && val[n - 1] == '"') {
				val[n - 1] = 0;
				val++;
			}
			rc = key_value(o, trim(s), val, err, &at, depth);
		} else {
			/* Switches, possibly several on a line. */
			char *tok = strtok(s, " \t");
			while (tok && !rc) {
				rc = one_arg(o, tok, err, &at, depth);
				tok = strtok(NULL, " \t");
			}
		}
	}
	fclose(f);
	return rc;
}

static bool has_suffix_ci(const char *s, const char *suf)
{
	size_t n = strlen(s), m = strlen(suf);
	return n >= m && strcasecmp(s + n - m, suf) == 0;
}

static int one_arg(struct options *o, const char *a, FILE *err, const struct origin *at, int depth)
{
	if (strcmp(a, "-") == 0) {
		set_str(&o->input, "-");
		return 0;
	}
	if ((a[0] == '+' || a[0] == '-') && a[1])
		return switch_arg(o, a[0], a + 1, err, at);
	const char *eq = strchr(a, '=');
	if (eq && eq != a) {
		char key[256];
		size_t n = (size_t)(eq - a);
		if (n >= sizeof key) n = sizeof key - 1;
		memcpy(key, a, n);
		key[n] = 0;
		return key_value(o, key, eq + 1, err, at, depth);
	}
	if (has_suffix_ci(a, ".ini"))
		return read_ini(o, a, err, depth + 1);
	set_str(&o->input, a);
	return 0;
}

int options_parse(struct options *o, int argc, char **argv, FILE *err)
{
	struct origin cmd = {NULL, 0};
	for (int i = 1; i < argc; i++) {
		const char *a = argv[i];
		if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
			o->help = true;
			continue;
		}
		if (strcmp(a, "--version") == 0) {
			o->version = true;
			continue;
		}
		if (strcmp(a, "--io-unrestricted") == 0) {
			o->io_unrestricted = true;
			continue;
		}
		if (strcmp(a, "--limit") == 0 || strncmp(a, "--limit=", 8) == 0) {
			const char *v = a[7] == '=' ? a + 8 : i + 1 < argc ? argv[++i] : NULL;
			const char *eq = v ? strchr(v, '=') : NULL;
			char *end = NULL;
			double n = eq ? strtod(eq + 1, &end) : 0;
			if (!eq || end == eq + 1 || *end || !(n >= 1) || n > 1e15) {
				report(err, &cmd, "error", "--limit needs NAME=N with N a positive number, not '%s'", v ? v : "");
				return 1;
			}
			char name[64];
			snprintf(name, sizeof name, "%.*s", (int)(eq - v), v);
			if (strcmp(name, "image-size") == 0)
				o->max_image = n;
			else if (!parse_limits_set(&o->limits, name, (size_t)n)) {
				report(err, &cmd, "error", "unknown limit '%s' (macro-depth, include-depth, expr-depth, csg-depth, "
				       "array-size, string-length, mesh-size, image-size)", name);
				return 1;
			}
			continue;
		}
		if (strcmp(a, "--signature") == 0) {
			o->signature = true;
			continue;
		}
		if (strcmp(a, "-q") == 0 || strcmp(a, "--quiet") == 0) {
			o->quiet = true;
			continue;
		}
		if (strcmp(a, "--threads") == 0 || strcmp(a, "--output") == 0) {
			if (i + 1 >= argc) {
				report(err, &cmd, "error", "'%s' needs a value", a);
				return 1;
			}
			char buf[4096];
			snprintf(buf, sizeof buf, "%s%s", a[2] == 't' ? "WT" : "O", argv[++i]);
			if (switch_arg(o, '+', buf, err, &cmd))
				return 1;
			continue;
		}
		if (strncmp(a, "--threads=", 10) == 0 || strncmp(a, "--output=", 9) == 0) {
			char buf[4096];
			const char *v = strchr(a, '=') + 1;
			snprintf(buf, sizeof buf, "%s%s", a[2] == 't' ? "WT" : "O", v);
			if (switch_arg(o, '+', buf, err, &cmd))
				return 1;
			continue;
		}
		if (strncmp(a, "--", 2) == 0) {
			report(err, &cmd, "error", "unknown option '%s' (see lucent --help)", a);
			return 1;
		}
		if (one_arg(o, a, err, &cmd, 0))
			return 1;
	}
	return 0;
}

int options_bound(double v, int size, bool is_end)
{
	int r;
	/* 1 itself is the first pixel as a start and the whole size as an end. */
	if (v > 0 && (v < 1 || (v == 1 && is_end)))
		r = (int)(v * size); /* a fraction of the size */
	else
		r = is_end ? (int)v : (int)v - 1; /* a 1-based pixel number */
	if (r < 0) r = 0;
	if (r > size) r = size;
	return r;
}

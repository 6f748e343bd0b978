/* test_options.c: unit tests for command-line and .ini parsing
 * (src/options.h): POV-Ray switches, GNU long options, Key=Value
 * settings, .ini files and their error messages, and the partial-render
 * bound rule of options_bound. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "options.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* One parse: the options, the return code and what went to err. */
struct run {
	struct options o;
	int rc;
	char *msg;
	size_t len;
};

/* Parse a NULL-terminated argument list (without argv[0]). */
static void run_args(struct run *r, const char *const *args)
{
	char *argv[64];
	int argc = 0;
	argv[argc++] = (char *)"lucent";
	for (; *args; args++) {
		assert_true(argc < 63);
		argv[argc++] = (char *)*args;
	}
	argv[argc] = NULL;
	r->msg = NULL;
	r->len = 0;
	FILE *err = open_memstream(&r->msg, &r->len);
	assert_non_null(err);
	options_init(&r->o);
	r->rc = options_parse(&r->o, argc, argv, err);
	fclose(err);
}

#define RUN(r, ...) run_args((r), (const char *const[]){__VA_ARGS__, NULL})

static void run_free(struct run *r)
{
	options_free(&r->o);
	free(r->msg);
}

/* A parse that must succeed silently. */
#define RUN_OK(r, ...)                                                                \
	do {                                                                         \
		RUN(r, __VA_ARGS__);                                                 \
		if ((r)->rc != 0 || (r)->len != 0)                                   \
			fail_msg("rc %d, messages: %s", (r)->rc, (r)->msg);          \
	} while (0)

static void assert_contains(const char *hay, const char *needle)
{
	if (!hay || !strstr(hay, needle))
		fail_msg("expected \"%s\" in:\n%s", needle, hay ? hay : "(null)");
}

/* A folder for .ini files, removed with everything in it afterwards. */
struct tmpdir {
	char path[64];
	char files[8][128];
	int nfiles;
};

static void tmp_open(struct tmpdir *t)
{
	strcpy(t->path, "/tmp/lucent-test-XXXXXX");
	assert_non_null(mkdtemp(t->path));
	t->nfiles = 0;
}

/* Write `text` to name in the folder; returns the full path (owned by t). */
static const char *tmp_write(struct tmpdir *t, const char *name, const char *text)
{
	assert_true(t->nfiles < 8);
	char *p = t->files[t->nfiles++];
	strcpy(p, t->path);
	assert_true(strlen(p) + 1 + strlen(name) < sizeof t->files[0]);
	strcat(p, "/");
	strcat(p, name);
	FILE *f = fopen(p, "w");
	assert_non_null(f);
	fputs(text, f);
	fclose(f);
	return p;
}

static void tmp_close(struct tmpdir *t)
{
	for (int i = 0; i < t->nfiles; i++)
		unlink(t->files[i]);
	rmdir(t->path);
}

static void test_defaults(void **state)
{
	(void)state;
	struct run r;
	RUN_OK(&r, "scene.pov");
	assert_int_equal(r.o.width, 800);
	assert_int_equal(r.o.height, 600);
	assert_int_equal(r.o.format, IMG_PNG);
	assert_false(r.o.format_set);
	assert_int_equal(r.o.bits, 8);
	assert_true(r.o.output_to_file);
	assert_null(r.o.output);
	assert_false(r.o.alpha);
	assert_false(r.o.quiet);
	assert_false(r.o.help);
	assert_false(r.o.version);
	assert_int_equal(r.o.threads, 0);
	assert_int_equal(r.o.verbose, 0);
	assert_int_equal(r.o.nlib_paths, 0);
	assert_int_equal(r.o.ndefines, 0);
	assert_true(r.o.start_row < 0 && r.o.end_row < 0 && r.o.start_col < 0 && r.o.end_col < 0);
	/* A bare name is the input. */
	assert_string_equal(r.o.input, "scene.pov");
	run_free(&r);
	/* No arguments at all. */
	RUN_OK(&r, "+W10");
	assert_null(r.o.input);
	run_free(&r);
}

static void test_size(void **state)
{
	(void)state;
	struct run r;
	RUN_OK(&r, "+W640", "+H480");
	assert_int_equal(r.o.width, 640);
	assert_int_equal(r.o.height, 480);
	run_free(&r);
	/* Case does not matter; the last one wins. */
	RUN_OK(&r, "+w320", "+h200", "+W100");
	assert_int_equal(r.o.width, 100);
	assert_int_equal(r.o.height, 200);
	run_free(&r);
	/* Bad sizes. */
	static const char *const bad[] = {"+W0", "+Wabc", "+W10.5", "+W", "+H-3", "+W70000"};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		RUN(&r, bad[i]);
		if (r.rc != 1)
			fail_msg("'%s' accepted", bad[i]);
		assert_contains(r.msg, "lucent: error: bad value in '");
		assert_contains(r.msg, bad[i]);
		run_free(&r);
	}
}

static void test_input(void **state)
{
	(void)state;
	struct run r;
	RUN_OK(&r, "+Ifile.pov");
	assert_string_equal(r.o.input, "file.pov");
	run_free(&r);
	RUN_OK(&r, "-");
	assert_string_equal(r.o.input, "-");
	run_free(&r);
	/* The last one given wins. */
	RUN_OK(&r, "a.pov", "+Ib.pov");
	assert_string_equal(r.o.input, "b.pov");
	run_free(&r);
	RUN(&r, "+I");
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "'+I' needs a file name");
	run_free(&r);
}

static void test_output_and_format(void **state)
{
	(void)state;
	struct run r;
	RUN_OK(&r, "+Oout.exr");
	assert_string_equal(r.o.output, "out.exr");
	/* The extension decides later: no +F, no format override. */
	assert_false(r.o.format_set);
	run_free(&r);
	RUN_OK(&r, "+FN16");
	assert_int_equal(r.o.format, IMG_PNG);
	assert_int_equal(r.o.bits, 16);
	assert_true(r.o.format_set);
	assert_true(r.o.output_to_file);
	run_free(&r);
	RUN_OK(&r, "+FE");
	assert_int_equal(r.o.format, IMG_EXR);
	assert_int_equal(r.o.bits, 8);
	assert_true(r.o.format_set);
	run_free(&r);
	static const struct { const char *arg; enum img_format f; } fmts[] = {
		{"+FH", IMG_HDR}, {"+FT", IMG_TGA}, {"+FC", IMG_TGA}, {"+FP", IMG_PPM},
		{"+FJ", IMG_JPEG}, {"+Fn", IMG_PNG}, {"+FN8", IMG_PNG},
	};
	for (size_t i = 0; i < sizeof fmts / sizeof fmts[0]; i++) {
		RUN_OK(&r, fmts[i].arg);
		assert_int_equal(r.o.format, fmts[i].f);
		run_free(&r);
	}
	/* -F: no file. +F alone: file output on, default format. */
	RUN_OK(&r, "-F");
	assert_false(r.o.output_to_file);
	run_free(&r);
	RUN_OK(&r, "-F", "+F");
	assert_true(r.o.output_to_file);
	assert_false(r.o.format_set);
	run_free(&r);
	/* Bad formats and bit depths. */
	RUN(&r, "+FX");
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "unknown output format in '+FX'");
	run_free(&r);
	RUN(&r, "+FN12");
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "must be 8 or 16");
	run_free(&r);
	RUN(&r, "+O");
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "needs a file name");
	run_free(&r);
}

static void test_alpha_lib_verbose(void **state)
{
	(void)state;
	struct run r;
	RUN_OK(&r, "+UA");
	assert_true(r.o.alpha);
	run_free(&r);
	RUN_OK(&r, "+UA", "-UA");
	assert_false(r.o.alpha);
	run_free(&r);
	RUN_OK(&r, "+Lone", "+L/two/dir", "+Lthree");
	assert_int_equal(r.o.nlib_paths, 3);
	assert_string_equal(r.o.lib_paths[0], "one");
	assert_string_equal(r.o.lib_paths[1], "/two/dir");
	assert_string_equal(r.o.lib_paths[2], "three");
	run_free(&r);
	RUN(&r, "+L");
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "needs a folder");
	run_free(&r);
	RUN_OK(&r, "+V");
	assert_int_equal(r.o.verbose, 1);
	run_free(&r);
	RUN_OK(&r, "+V", "-V");
	assert_int_equal(r.o.verbose, 0);
	run_free(&r);
}

static void test_partial_render_switches(void **state)
{
	(void)state;
	struct run r;
	RUN_OK(&r, "+SR0.25", "+ER0.75", "+SC10", "+EC20");
	assert_true(r.o.start_row == 0.25);
	assert_true(r.o.end_row == 0.75);
	assert_true(r.o.start_col == 10);
	assert_true(r.o.end_col == 20);
	run_free(&r);
	RUN(&r, "+SR-1");
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "must not be negative");
	run_free(&r);
}

static void test_threads(void **state)
{
	(void)state;
	struct run r;
	RUN_OK(&r, "+WT3");
	assert_int_equal(r.o.threads, 3);
	/* +WT is not +W. */
	assert_int_equal(r.o.width, 800);
	run_free(&r);
	RUN_OK(&r, "--threads", "2");
	assert_int_equal(r.o.threads, 2);
	run_free(&r);
	RUN_OK(&r, "--threads=2");
	assert_int_equal(r.o.threads, 2);
	run_free(&r);
	RUN(&r, "--threads");
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "'--threads' needs a value");
	run_free(&r);
	static const char *const bad[] = {"+WT0", "+WT1.5", "+WTx", "--threads=0", "--threads=2000"};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		RUN(&r, bad[i]);
		if (r.rc != 1)
			fail_msg("'%s' accepted", bad[i]);
		assert_contains(r.msg, "threads must be a whole number");
		run_free(&r);
	}
}

static void test_long_options(void **state)
{
	(void)state;
	struct run r;
	RUN_OK(&r, "--output", "x.png");
	assert_string_equal(r.o.output, "x.png");
	run_free(&r);
	RUN_OK(&r, "--output=y.exr", "scene.pov");
	assert_string_equal(r.o.output, "y.exr");
	assert_string_equal(r.o.input, "scene.pov");
	run_free(&r);
	RUN(&r, "--output");
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "needs a value");
	run_free(&r);
	RUN_OK(&r, "-q");
	assert_true(r.o.quiet);
	run_free(&r);
	RUN_OK(&r, "--quiet");
	assert_true(r.o.quiet);
	run_free(&r);
	/* POV-Ray's -GA (all console text off) means quiet too; +GA undoes it. */
	RUN_OK(&r, "-GA");
	assert_true(r.o.quiet);
	run_free(&r);
	RUN_OK(&r, "-GA", "+GA");
	assert_false(r.o.quiet);
	run_free(&r);
	RUN_OK(&r, "--help");
	assert_true(r.o.help);
	assert_false(r.o.version);
	run_free(&r);
	RUN_OK(&r, "-h");
	assert_true(r.o.help);
	run_free(&r);
	RUN_OK(&r, "--version");
	assert_true(r.o.version);
	assert_false(r.o.help);
	run_free(&r);
	RUN(&r, "--frobnicate");
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "lucent: error: unknown option '--frobnicate'");
	run_free(&r);
	RUN(&r, "--threadsx=2");
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "unknown option '--threadsx=2'");
	run_free(&r);
}

static void test_declare(void **state)
{
	(void)state;
	struct run r;
	RUN_OK(&r, "Declare=N=1.5", "declare=Other_2=-3e2");
	assert_int_equal(r.o.ndefines, 2);
	assert_string_equal(r.o.defines[0].name, "N");
	assert_true(r.o.defines[0].value == 1.5);
	assert_string_equal(r.o.defines[1].name, "Other_2");
	assert_true(r.o.defines[1].value == -300);
	run_free(&r);
	static const char *const bad[] = {"Declare=N=abc", "Declare=N", "Declare==3", "Declare=N=",
	                                  "Declare=1N=2", "Declare=a-b=2"};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		RUN(&r, bad[i]);
		if (r.rc != 1)
			fail_msg("'%s' accepted", bad[i]);
		assert_contains(r.msg, "lucent: error: Declare");
		assert_int_equal(r.o.ndefines, 0);
		run_free(&r);
	}
	/* Other Key=Value settings work on the command line too. */
	RUN_OK(&r, "Width=123", "Output_Alpha=on");
	assert_int_equal(r.o.width, 123);
	assert_true(r.o.alpha);
	run_free(&r);
}

static void test_unknown_switch(void **state)
{
	(void)state;
	struct run r;
	static const char *const unknown[] = {"+Zzz", "+Yes", "-N", "+UZ", "+Vx"};
	for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; i++) {
		RUN(&r, unknown[i]);
		if (r.rc != 1)
			fail_msg("'%s': rc %d, messages: %s", unknown[i], r.rc, r.msg);
		char want[64];
		snprintf(want, sizeof want, "lucent: error: unknown switch '%s'", unknown[i]);
		assert_contains(r.msg, want);
		run_free(&r);
	}
}

/* Antialiasing and quality: POV-Ray 3.7's defaults (its option listing
 * for +A alone: method 1, threshold 0.3, depth 3, jitter 1.00, gamma 2.50;
 * quality 9), and what each switch form sets. */
static void test_antialias(void **state)
{
	(void)state;
	struct run r;
	RUN_OK(&r, "scene.pov");
	assert_false(r.o.antialias);
	assert_true(r.o.aa_threshold == 0.3);
	assert_int_equal(r.o.aa_method, 1);
	assert_int_equal(r.o.aa_depth, 3);
	assert_true(r.o.jitter);
	assert_true(r.o.jitter_amount == 1.0);
	assert_true(r.o.aa_gamma == 2.5);
	assert_int_equal(r.o.quality, 9);
	run_free(&r);
	RUN_OK(&r, "+A0.1", "+AM2", "+R4", "-J", "+AG1.8", "+Q5");
	assert_true(r.o.antialias);
	assert_true(r.o.aa_threshold == 0.1);
	assert_int_equal(r.o.aa_method, 2);
	assert_int_equal(r.o.aa_depth, 4);
	assert_false(r.o.jitter);
	assert_true(r.o.aa_gamma == 1.8);
	assert_int_equal(r.o.quality, 5);
	run_free(&r);
	/* A value after -A or -J is kept for a later +A or +J. */
	RUN_OK(&r, "-A0.2", "-J0.4");
	assert_false(r.o.antialias);
	assert_false(r.o.jitter);
	assert_true(r.o.aa_threshold == 0.2);
	assert_true(r.o.jitter_amount == 0.4);
	run_free(&r);
	RUN_OK(&r, "-A0.2", "+A", "-J0.4", "+J");
	assert_true(r.o.antialias);
	assert_true(r.o.aa_threshold == 0.2);
	assert_true(r.o.jitter);
	assert_true(r.o.jitter_amount == 0.4);
	run_free(&r);
	/* +J0 turns jitter off (the manual: an amount <= 0 does). */
	RUN_OK(&r, "+J0");
	assert_false(r.o.jitter);
	run_free(&r);
	RUN(&r, "+R0");
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "bad value in '+R0'");
	run_free(&r);
	RUN(&r, "+AM3");
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "the sampling method is 1 or 2");
	run_free(&r);
}

static void test_unimplemented_switch(void **state)
{
	(void)state;
	struct run r;
	RUN(&r, "+MB3", "scene.pov");
	assert_int_equal(r.rc, 0);
	assert_contains(r.msg, "lucent: warning: switch '+MB3'");
	assert_contains(r.msg, "bounding threshold");
	assert_contains(r.msg, "not implemented");
	/* The rest of the line is still read. */
	assert_string_equal(r.o.input, "scene.pov");
	run_free(&r);
	RUN(&r, "+UR");
	assert_int_equal(r.rc, 0);
	assert_contains(r.msg, "switch '+UR' (remove bounds)");
	run_free(&r);
	/* Turning off something lucent never does is silent. */
	RUN_OK(&r, "-P");
	run_free(&r);
	RUN(&r, "+P");
	assert_int_equal(r.rc, 0);
	assert_contains(r.msg, "'+P'");
	run_free(&r);
	/* The preview display: warned when turned on, silent when off. */
	RUN(&r, "+D");
	assert_int_equal(r.rc, 0);
	assert_contains(r.msg, "warning: switch '+D'");
	run_free(&r);
	RUN_OK(&r, "-D");
	run_free(&r);
}

static void test_ini_file(void **state)
{
	(void)state;
	struct tmpdir t;
	tmp_open(&t);
	const char *ini = tmp_write(&t, "a.ini",
		"; a comment line\n"
		"[Section One]\n"
		"Width=320\n"
		"  Height = 200   ; a trailing comment\n"
		"\n"
		"Input_File_Name=a.pov\n"
		"+WT2 -UA\n"
		"Library_Path=\"x\"\n"
		"Library_Path=y dir\n"
		"Declare=K=2\n"
		"Output_File_Name=out.png\n"
		"Output_to_File=off\n"
		"Bits_Per_Color=16\n"
		"Verbose=yes\n"
		"Clock=0.5\n"
		"Display=off\n");
	struct run r;
	RUN_OK(&r, ini);
	assert_int_equal(r.o.width, 320);
	assert_int_equal(r.o.height, 200);
	assert_string_equal(r.o.input, "a.pov");
	assert_int_equal(r.o.threads, 2);
	assert_false(r.o.alpha);
	assert_int_equal(r.o.nlib_paths, 2);
	assert_string_equal(r.o.lib_paths[0], "x");
	assert_string_equal(r.o.lib_paths[1], "y dir");
	assert_int_equal(r.o.ndefines, 1);
	assert_string_equal(r.o.defines[0].name, "K");
	assert_true(r.o.defines[0].value == 2);
	assert_string_equal(r.o.output, "out.png");
	assert_false(r.o.output_to_file);
	assert_int_equal(r.o.bits, 16);
	assert_int_equal(r.o.verbose, 1);
	assert_true(r.o.clock == 0.5);
	run_free(&r);
	/* The command line after the .ini overrides it, and the other way round. */
	RUN_OK(&r, ini, "+W64");
	assert_int_equal(r.o.width, 64);
	run_free(&r);
	RUN_OK(&r, "+W64", ini);
	assert_int_equal(r.o.width, 320);
	run_free(&r);
	tmp_close(&t);
}

static void test_ini_errors(void **state)
{
	(void)state;
	struct tmpdir t;
	tmp_open(&t);
	char want[256];
	struct run r;

	/* An unknown key: file and line. */
	const char *bad = tmp_write(&t, "bad.ini", "Width=10\n; comment\nBogus_Key=3\nHeight=5\n");
	RUN(&r, bad);
	assert_int_equal(r.rc, 1);
	snprintf(want, sizeof want, "%s:3: error: unknown option 'Bogus_Key'", bad);
	assert_contains(r.msg, want);
	assert_int_equal(r.o.width, 10);
	/* Reading stops at the error. */
	assert_int_equal(r.o.height, 600);
	run_free(&r);

	/* A bad switch on a line of switches. */
	const char *bsw = tmp_write(&t, "bsw.ini", "[x]\n+W10 +H0\n");
	RUN(&r, bsw);
	assert_int_equal(r.rc, 1);
	snprintf(want, sizeof want, "%s:2: error: bad value in '+H0'", bsw);
	assert_contains(r.msg, want);
	run_free(&r);

	/* A bad value for a known key. */
	const char *bval = tmp_write(&t, "bval.ini", "Output_Alpha=maybe\n");
	RUN(&r, bval);
	assert_int_equal(r.rc, 1);
	snprintf(want, sizeof want, "%s:1: error: Output_Alpha wants on or off, not 'maybe'", bval);
	assert_contains(r.msg, want);
	run_free(&r);

	/* An unimplemented key: a warning with the place, then carry on. */
	const char *unimp = tmp_write(&t, "unimp.ini", "Remove_Bounds=on\nWidth=33\n");
	RUN(&r, unimp);
	assert_int_equal(r.rc, 0);
	snprintf(want, sizeof want, "%s:1: warning: option 'Remove_Bounds' is not implemented", unimp);
	assert_contains(r.msg, want);
	assert_int_equal(r.o.width, 33);
	run_free(&r);

	/* A missing file. */
	snprintf(want, sizeof want, "%s/missing.ini", t.path);
	RUN(&r, want);
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "lucent: error: cannot read ini file '");
	assert_contains(r.msg, "missing.ini");
	run_free(&r);

	/* Includes: one level works; a file including itself is stopped. */
	char text[256];
	const char *inner = tmp_write(&t, "inner.ini", "Height=77\n");
	snprintf(text, sizeof text, "Include_Ini=%s\nWidth=88\n", inner);
	const char *outer = tmp_write(&t, "outer.ini", text);
	RUN_OK(&r, outer);
	assert_int_equal(r.o.height, 77);
	assert_int_equal(r.o.width, 88);
	run_free(&r);
	char self[128];
	snprintf(self, sizeof self, "%s/self.ini", t.path);
	snprintf(text, sizeof text, "Include_Ini=%s\n", self);
	tmp_write(&t, "self.ini", text);
	RUN(&r, self);
	assert_int_equal(r.rc, 1);
	assert_contains(r.msg, "too deeply");
	run_free(&r);
	tmp_close(&t);
}

static void test_bound(void **state)
{
	(void)state;
	/* 0 < v < 1: a fraction of the size. */
	assert_int_equal(options_bound(0.5, 120, false), 60);
	assert_int_equal(options_bound(0.75, 120, true), 90);
	assert_int_equal(options_bound(0.5, 120, true), 60);
	assert_int_equal(options_bound(0.25, 100, false), 25);
	/* Otherwise a 1-based pixel number: a start becomes 0-based, an end
	 * is exclusive. */
	assert_int_equal(options_bound(10, 120, false), 9);
	assert_int_equal(options_bound(10, 120, true), 10);
	assert_int_equal(options_bound(1, 120, false), 0);
	assert_int_equal(options_bound(120, 120, true), 120);
	assert_int_equal(options_bound(120, 120, false), 119);
	/* As an end bound, 1.0 is the whole size. */
	assert_int_equal(options_bound(1.0, 120, true), 120);
	/* Clamped to the image. */
	assert_int_equal(options_bound(500, 120, true), 120);
	assert_int_equal(options_bound(500, 120, false), 120);
	assert_int_equal(options_bound(0, 120, false), 0);
	assert_int_equal(options_bound(0, 120, true), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_defaults),
		cmocka_unit_test(test_size),
		cmocka_unit_test(test_input),
		cmocka_unit_test(test_output_and_format),
		cmocka_unit_test(test_alpha_lib_verbose),
		cmocka_unit_test(test_partial_render_switches),
		cmocka_unit_test(test_threads),
		cmocka_unit_test(test_long_options),
		cmocka_unit_test(test_declare),
		cmocka_unit_test(test_unknown_switch),
		cmocka_unit_test(test_antialias),
		cmocka_unit_test(test_unimplemented_switch),
		cmocka_unit_test(test_ini_file),
		cmocka_unit_test(test_ini_errors),
		cmocka_unit_test(test_bound),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

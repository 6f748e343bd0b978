/* fuzz_common.h: the body shared by the libFuzzer harnesses (fuzz_parse.c,
 * fuzz_render.c). Each input is a scene file: it is written to a private
 * temporary folder (the process works there, so every file the scene
 * reads or writes stays inside it under lucent's file rule), parsed with
 * a bound on the directives it may run (an endless #while is the user's to
 * stop, not a bug), and, when FUZZ_RENDER is 1, prepared and rendered to a
 * tiny image that is never written out. */
#include "image/framebuffer.h"
#include "lang/diag.h"
#include "lang/intern.h"
#include "lang/lex.h"
#include "lang/parse.h"
#include "lang/source.h"
#include "render/prepare.h"
#include "render/render.h"
#include "scene/fn.h"
#include "scene/scene.h"

#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef FUZZ_STDLIB
#define FUZZ_STDLIB "stdlib"
#endif

/* Bounds for one input: endless loops stop after FUZZ_MAX_STEPS
 * directives and macro calls, and sizes are capped low, so that a loop
 * growing a string or an array (quadratic work) stays far under the
 * one-second hang threshold. Macro calls nest at most FUZZ_MAX_DEPTH deep
 * (lucent's default is 1000): a mutated test that recursed 1000 deep,
 * building a text object at each level, held 193 MB and took 0.23 s of CPU
 * built normally, 3 to 3.6 s under the sanitizers (run 18). Strings are
 * capped lower than arrays: a loop that appends n bytes per turn copies
 * about steps x length / 2 bytes in all, 2.5 GB at the worst n for a cap of
 * 1000000 (an endless #while appending 90 bytes per turn took 2.2 s under
 * the sanitizers, run 19b); with 100000 the same loop still took 0.55 s of
 * CPU, and over a second inside the fuzzer (run 22): 20000. */
enum { FUZZ_MAX_STEPS = 5000, FUZZ_MAX_SIZE = 1000000, FUZZ_MAX_STRING = 20000, FUZZ_MAX_DEPTH = 100,
       FUZZ_W = 8, FUZZ_H = 6 };

/* The stdlib's files are read and lexed once, into a source manager kept
 * across inputs: an input's own files are forgotten after it
 * (src_truncate), and so are the names it interned (intern_rollback), so
 * that an input allocates nothing it does not free and libFuzzer's leak
 * check stays exact. An input that includes a stdlib file after writing
 * some file reads it afresh, as lucent always does (the file may be the
 * one it wrote). A stdlib file that does not lex is not kept (an include
 * of it lexes it, and reports the error, every time). */
static char fuzz_dir[64], fuzz_scene[96];
static FILE *fuzz_null;
static struct srcmgr *fuzz_base;
static size_t fuzz_base_files;

static void fuzz_base_new(void)
{
	fuzz_base = src_new();
	struct diag diag;
	diag_init(&diag, fuzz_base, fuzz_null);
	DIR *d = opendir(FUZZ_STDLIB);
	if (!d)
		abort();
	struct dirent *e;
	char path[512];
	while ((e = readdir(d)) != NULL)
		if (e->d_name[0] != '.') {
			snprintf(path, sizeof path, "%s/%s", FUZZ_STDLIB, e->d_name);
			uint32_t file = src_load(fuzz_base, path);
			if (!file)
				abort();
			if (!lex_file(fuzz_base, file, &diag))
				src_truncate(fuzz_base, file);
		}
	closedir(d);
	fuzz_base_files = fuzz_base->nfiles;
}

/* Remove what the last input left in the folder (files it wrote). The
 * scene file itself stays, to be overwritten: creating a file costs more
 * than everything else the harness does per input (measured with perf). */
static void fuzz_clean(void)
{
	DIR *d = opendir(fuzz_dir);
	if (!d)
		return;
	struct dirent *e;
	char path[512];
	while ((e = readdir(d)) != NULL)
		if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0 &&
		    strcmp(e->d_name, "scene.pov") != 0) {
			snprintf(path, sizeof path, "%s/%s", fuzz_dir, e->d_name);
			unlink(path);
		}
	closedir(d);
}

static void fuzz_cleanup_dir(void)
{
	src_free(fuzz_base);
	fuzz_base = NULL;
	fuzz_clean();
	unlink(fuzz_scene);
	rmdir(fuzz_dir);
}

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
	(void)argc;
	(void)argv;
	/* In memory (tmpfs) where there is one: every input is a file. */
	snprintf(fuzz_dir, sizeof fuzz_dir, "/dev/shm/lucent-fuzz-XXXXXX");
	if (!mkdtemp(fuzz_dir)) {
		snprintf(fuzz_dir, sizeof fuzz_dir, "/tmp/lucent-fuzz-XXXXXX");
		if (!mkdtemp(fuzz_dir)) {
			perror("lucent fuzz: temporary folder");
			abort();
		}
	}
	snprintf(fuzz_scene, sizeof fuzz_scene, "%s/scene.pov", fuzz_dir);
	atexit(fuzz_cleanup_dir);
	fuzz_null = fopen("/dev/null", "w");
	if (!fuzz_null)
		abort();
	fuzz_base_new();
	/* sum() and prod() over more terms are cut short, as endless loops are
	 * by FUZZ_MAX_STEPS (run 12's hang: a sum over 8.9e89 terms). */
	fn_set_max_terms(1e6);
	return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	fuzz_clean();
	FILE *f = fopen(fuzz_scene, "wb");
	if (!f)
		abort();
	if (size && fwrite(data, 1, size, f) != size)
		abort();
	fclose(f);

	struct srcmgr *sm = fuzz_base;
	intern_mark(sm->names);
	struct diag diag;
	diag_init(&diag, sm, fuzz_null);
	struct scene *scene = scene_new();
	struct parse_opts po = {
		.input = fuzz_scene,
		.stdlib_dir = FUZZ_STDLIB,
		.image_width = FUZZ_W,
		.image_height = FUZZ_H,
		.debug_out = fuzz_null,
		.max_steps = FUZZ_MAX_STEPS,
		.limits = {.macro_depth = FUZZ_MAX_DEPTH, .array_size = FUZZ_MAX_SIZE, .string_length = FUZZ_MAX_STRING,
		           .mesh_size = FUZZ_MAX_SIZE},
	};
	int rc = parse_scene(sm, &diag, &po, scene);
	if (FUZZ_RENDER && rc == 0) {
		struct prepared *prep = prepare_scene(scene);
		prepare_quality(prep, 9);
		struct framebuffer *fb = fb_new(FUZZ_W, FUZZ_H);
		struct render_opts ro = {
			.width = FUZZ_W, .height = FUZZ_H,
			.row0 = 0, .row1 = FUZZ_H, .col0 = 0, .col1 = FUZZ_W,
			.threads = 1,
			.aa_method = 1, .aa_threshold = 0.3, .aa_depth = 2,
			.aa_exponent = 1,
		};
		struct stats st;
		memset(&st, 0, sizeof st);
		render_image(prep, &ro, fb, &st);
		fb_free(fb);
		prepared_free(prep);
	}
	scene_free(scene);
	src_truncate(sm, fuzz_base_files);
	intern_rollback(sm->names);
	return 0;
}

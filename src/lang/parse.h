/* parse.h: the language front end's one entry point. It reads a scene
 * file, runs its directives and builds the scene through the builder API;
 * it never reaches into the renderer. */
#ifndef LUCENT_PARSE_H
#define LUCENT_PARSE_H

#include "lang/diag.h"
#include "lang/source.h"
#include "scene/scene.h"

#include <signal.h>
#include <stdio.h>

struct parse_define {
	const char *name;
	double value;
};

struct parse_opts {
	const char *input;              /* scene path, or "-" for standard input */
	const char *const *lib_paths;   /* +L folders, searched in order */
	size_t nlib_paths;
	const char *stdlib_dir;         /* lucent's include library; may be NULL */
	const struct parse_define *defines; /* Declare=NAME=VALUE */
	size_t ndefines;
	int image_width, image_height;  /* for the built-in identifiers */
	double clock;
	FILE *debug_out;                /* where #debug text goes */
	bool io_unrestricted;           /* #fopen may reach any path */
	/* Set (by a signal handler) to stop the parse: it stops at the next
	 * directive or macro call, reports where it was and returns 2. May be
	 * NULL. */
	volatile sig_atomic_t *stop;
	/* If not 0: the most directives and macro calls the parse may run
	 * before it stops with an error (the fuzz harnesses bound endless
	 * loops with it). */
	unsigned long max_steps;
};

/* Parse o->input into s. Returns 0 on success, 1 after reporting an error
 * through d, 2 if stopped through o->stop (reported through d). All parse-time memory is released on both paths; what the
 * scene received belongs to the scene. */
int parse_scene(struct srcmgr *sm, struct diag *d, const struct parse_opts *o, struct scene *s);

#endif

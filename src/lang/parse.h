/* parse.h: the language front end's one entry point. It reads a scene
 * file, runs its directives and builds the scene through the builder API;
 * it never reaches into the renderer. */
#ifndef LUCENT_PARSE_H
#define LUCENT_PARSE_H

#include "lang/diag.h"
#include "lang/source.h"
#include "scene/scene.h"

#include <signal.h>
#include <stdbool.h>
#include <stdio.h>

struct parse_define {
	const char *name;
	double value;
};

/* The bounds a scene runs within (doc/reliability.md). Each is raised with
 * `lucent --limit NAME=N`, and the error that meets one names it. A field
 * left 0 takes its default (parse_limits_default). */
struct parse_limits {
	size_t macro_depth;    /* macro-depth: macro calls nested in each other */
	size_t include_depth;  /* include-depth: #include nested */
	size_t expr_depth;     /* expr-depth: expression nesting */
	size_t csg_depth;      /* csg-depth: objects nested in CSG */
	size_t array_size;     /* array-size: elements of one array */
	size_t string_length;  /* string-length: bytes of one string */
	size_t mesh_size;      /* mesh-size: vertices, normals, uvs or faces of one mesh */
};

/* Fill l with the defaults. */
void parse_limits_default(struct parse_limits *l);
/* Set the limit NAME (a field name above, with '-') to value; false if
 * there is no such limit. */
bool parse_limits_set(struct parse_limits *l, const char *name, size_t value);

/* Would n items of size bytes fit in the machine's physical memory? (A
 * request visible in advance fails with an error, not the OOM killer.) */
bool parse_memory_ok(size_t n, size_t size);

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
	struct parse_limits limits;     /* 0 fields: the defaults */
};

/* Parse o->input into s. Returns 0 on success, 1 after reporting an error
 * through d, 2 if stopped through o->stop (reported through d). All parse-time memory is released on both paths; what the
 * scene received belongs to the scene. */
int parse_scene(struct srcmgr *sm, struct diag *d, const struct parse_opts *o, struct scene *s);

#endif

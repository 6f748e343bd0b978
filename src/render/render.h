/* render.h: the render stage: camera rays over tiles on POSIX threads into
 * a float framebuffer. */
#ifndef LUCENT_RENDER_H
#define LUCENT_RENDER_H

#include "image/framebuffer.h"
#include "render/prepare.h"
#include "render/stats.h"

#include <signal.h>
#include <stdbool.h>

enum { RENDER_BLOCK = 32 };

struct render_opts {
	int width, height;
	int row0, row1;   /* rows [row0, row1) to render, 0-based */
	int col0, col1;   /* columns [col0, col1) */
	int threads;      /* >= 1 */
	bool progress;    /* draw a progress bar on stderr */
	/* Antialiasing, as POV-Ray 3.7's +A, +AM, +R, +J and +AG (see
	 * doc/rendering.md). */
	int aa_method;       /* 0: one sample at each pixel centre; 1: adaptive; 2: recursive adaptive */
	double aa_threshold; /* supersample where colours differ by at least this */
	int aa_depth;        /* 1 to 9: method 1 takes depth x depth more samples, method 2 subdivides depth-1 times */
	double jitter;       /* 0: none; up to 1: samples move within their cell */
	double aa_exponent;  /* colours are compared raised to this power (working gamma / +AG) */
	bool alpha;          /* +UA: the comparison counts the transmit channel too */
	/* Set (by a signal handler) to ask the render to stop; may be NULL. */
	volatile sig_atomic_t *stop;
};

/* Render into fb (already width x height, cleared). Returns false if
 * stopped through opts->stop. Statistics are summed into *stats.
 * Tiles are RENDER_BLOCK pixels square from (col0, row0), as POV-Ray's
 * render blocks: antialiasing method 1 compares a pixel with its
 * neighbours inside its block and with the row above and the column left
 * of it, so the block grid is part of the result (but the thread count and
 * the order tiles are taken in are not). */
bool render_image(const struct prepared *p, const struct render_opts *opts, struct framebuffer *fb, struct stats *stats);

#endif

/* render.h: the render stage: camera rays over tiles on POSIX threads into
 * a float framebuffer. */
#ifndef LUCENT_RENDER_H
#define LUCENT_RENDER_H

#include "image/framebuffer.h"
#include "render/prepare.h"
#include "render/stats.h"

#include <signal.h>
#include <stdbool.h>

struct render_opts {
	int width, height;
	int row0, row1;   /* rows [row0, row1) to render, 0-based */
	int col0, col1;   /* columns [col0, col1) */
	int threads;      /* >= 1 */
	bool progress;    /* draw a progress bar on stderr */
	/* Set (by a signal handler) to ask the render to stop; may be NULL. */
	volatile sig_atomic_t *stop;
};

/* Render into fb (already width x height, cleared). Returns false if
 * stopped through opts->stop. Statistics are summed into *stats. */
bool render_image(const struct prepared *p, const struct render_opts *opts, struct framebuffer *fb, struct stats *stats);

#endif

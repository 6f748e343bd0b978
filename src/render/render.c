/* render.c: tiles over threads (see render.h). Threads take tiles from a
 * shared atomic counter; each pixel depends only on its own coordinates, so
 * the image is the same whatever the thread count or tile order. */
#include "render/render.h"

#include "render/camsample.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { TILE = 32 };

struct job {
	const struct prepared *p;
	const struct render_opts *o;
	struct framebuffer *fb;
	int tiles_x, tiles_y, ntiles;
	atomic_int next;   /* next tile to take */
	atomic_int done;   /* tiles finished */
	atomic_bool stopped;
};

struct worker {
	struct job *job;
	struct tracer tr;
	pthread_t thread;
};

static void render_tile(struct worker *w, int tile)
{
	struct job *j = w->job;
	const struct render_opts *o = j->o;
	int tx = tile % j->tiles_x, ty = tile / j->tiles_x;
	int x0 = o->col0 + tx * TILE, y0 = o->row0 + ty * TILE;
	int x1 = x0 + TILE < o->col1 ? x0 + TILE : o->col1;
	int y1 = y0 + TILE < o->row1 ? y0 + TILE : o->row1;
	for (int y = y0; y < y1; y++)
		for (int x = x0; x < x1; x++) {
			bool any;
			rgb c = camera_sample(&w->tr, x + 0.5, y + 0.5, o->width, o->height, x, y, 0, &any);
			float *px = fb_pixel(j->fb, x, y);
			px[0] = (float)c.r;
			px[1] = (float)c.g;
			px[2] = (float)c.b;
			/* With +UA the background is transparent, as in POV-Ray. */
			px[3] = any ? 1.0f : 0.0f;
			w->tr.stats.pixels++;
			w->tr.stats.samples++;
		}
}

static void *worker_main(void *arg)
{
	struct worker *w = arg;
	struct job *j = w->job;
	for (;;) {
		if (j->o->stop && *j->o->stop) {
			atomic_store(&j->stopped, true);
			break;
		}
		int t = atomic_fetch_add(&j->next, 1);
		if (t >= j->ntiles)
			break;
		render_tile(w, t);
		atomic_fetch_add(&j->done, 1);
	}
	return NULL;
}

static double now_seconds(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static void fmt_time(char *buf, size_t n, double s)
{
	int t = (int)(s + 0.5);
	snprintf(buf, n, "%d:%02d:%02d", t / 3600, t / 60 % 60, t % 60);
}

static void draw_progress(int done, int total, double elapsed)
{
	double frac = total ? (double)done / total : 1.0;
	char el[32], left[32];
	fmt_time(el, sizeof el, elapsed);
	if (frac > 0)
		fmt_time(left, sizeof left, elapsed / frac - elapsed);
	else
		snprintf(left, sizeof left, "--:--:--");
	enum { BAR = 30 };
	char bar[BAR + 1];
	int fill = (int)(frac * BAR);
	for (int i = 0; i < BAR; i++)
		bar[i] = i < fill ? '#' : '.';
	bar[BAR] = 0;
	fprintf(stderr, "\rrender [%s] %3d%%  elapsed %s  left %s ", bar, (int)(frac * 100), el, left);
	fflush(stderr);
}

bool render_image(const struct prepared *p, const struct render_opts *o, struct framebuffer *fb, struct stats *stats)
{
	struct job j = {.p = p, .o = o, .fb = fb};
	int rw = o->col1 - o->col0, rh = o->row1 - o->row0;
	j.tiles_x = (rw + TILE - 1) / TILE;
	j.tiles_y = (rh + TILE - 1) / TILE;
	j.ntiles = rw > 0 && rh > 0 ? j.tiles_x * j.tiles_y : 0;
	atomic_init(&j.next, 0);
	atomic_init(&j.done, 0);
	atomic_init(&j.stopped, false);
	int nt = o->threads < 1 ? 1 : o->threads;
	if (nt > j.ntiles && j.ntiles > 0)
		nt = j.ntiles;
	struct worker *w = calloc((size_t)nt, sizeof *w);
	if (!w) abort();
	int started = 0;
	for (int i = 0; i < nt; i++) {
		w[i].job = &j;
		tracer_init(&w[i].tr, p);
	}
	/* Thread 0's work runs in workers started like the others; the calling
	 * thread draws progress. */
	for (int i = 0; i < nt; i++) {
		if (pthread_create(&w[i].thread, NULL, worker_main, &w[i]) != 0)
			break;
		started++;
	}
	if (started == 0)
		worker_main(&w[0]); /* no threads available: render here */
	double t0 = now_seconds();
	if (o->progress && started > 0) {
		while (atomic_load(&j.done) < j.ntiles && !atomic_load(&j.stopped)) {
			draw_progress(atomic_load(&j.done), j.ntiles, now_seconds() - t0);
			nanosleep(&(struct timespec){0, 100000000}, NULL);
		}
	}
	for (int i = 0; i < started; i++)
		pthread_join(w[i].thread, NULL);
	if (o->progress) {
		draw_progress(atomic_load(&j.done), j.ntiles, now_seconds() - t0);
		fputc('\n', stderr);
	}
	for (int i = 0; i < nt; i++) {
		stats_add(stats, &w[i].tr.stats);
		tracer_free(&w[i].tr);
	}
	free(w);
	return !atomic_load(&j.stopped) && atomic_load(&j.done) == j.ntiles;
}

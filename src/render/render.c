/* render.c: tiles over threads, and the pixel samplers (see render.h).
 * Threads take tiles from a shared atomic counter. A pixel depends only on
 * its coordinates and its block (the tile it lies in, fixed by the render
 * region and not by the threads), so the image is the same whatever the
 * thread count or tile order. Random choices (jitter) are hashes of the
 * sample's coordinates (math/hash.h).
 *
 * The samplers follow what POV-Ray 3.7 renders, measured with scenes whose
 * colour is a known function of the image position (doc/rendering.md):
 *  - no antialiasing: one sample at the pixel centre (x + 0.5, y + 0.5);
 *  - method 1: every pixel gets its centre sample; then, in raster order
 *    within the block, a pixel whose centre colour differs by at least the
 *    threshold from the current colour of its left or upper neighbour is
 *    supersampled, and so is that neighbour if it lies in the block: the
 *    new colour is the mean of the centre sample and depth x depth samples
 *    at the centres of a depth x depth grid over the pixel. The first
 *    column and row of a block compare with the column left and the row
 *    above it (traced again here), never the other way round;
 *  - method 2: the pixel's four corner samples are averaged, or, if two of
 *    them (diagonals too) differ by at least the threshold and fewer than
 *    depth - 1 subdivisions were made, the means of its four quarters,
 *    each treated the same way;
 *  - colours are compared as the sum over r, g and b of the absolute
 *    differences of c^e, with c the unclipped linear colour and e =
 *    (working gamma) / +AG; samples are averaged unclipped. */
#include "render/render.h"

#include "math/hash.h"
#include "render/camsample.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { TILE = RENDER_BLOCK };

/* Hash purposes of the jitter offsets. */
enum { JITTER_X = 0x4a495458u, JITTER_Y = 0x4a495459u };

/* One sample, or the mean of several: its colour, coverage (1 - the
 * share of the background seen through it, for the alpha channel) and
 * comparison values. */
struct smp {
	rgb c;
	double alpha;
	double g[4];   /* c^aa_exponent per channel; with +UA the transmit (else 0) */
	bool super;    /* method 1: already supersampled */
};

/* Method 2's caches: the corner samples of a tile, and the samples inside
 * the pixel being computed, each valid while its stamp is current. */
struct m2cache {
	int n;              /* subdivisions of a pixel side: 2^(depth-1) */
	struct smp *corner; /* (TILE + 1)^2 */
	uint32_t *corner_stamp;
	struct smp *inner;  /* (n + 1)^2 */
	uint32_t *inner_stamp;
	uint32_t tile_stamp, pixel_stamp;
};

struct job {
	const struct prepared *p;
	const struct render_opts *o;
	struct framebuffer *fb;
	int tiles_x, tiles_y, ntiles;
	atomic_int next;   /* next tile to take */
	atomic_int done;   /* tiles finished */
	atomic_bool stopped;
};

/* The last value set_compare raised to aa_exponent per channel, and the
 * result: flat areas (a background, a plain colour, a checker's two
 * colours) give the same channel values again and again, and pow is the
 * dearest step of a method 2 sample on such a scene. */
struct pow_memo {
	double in[3], out[3];
};

struct worker {
	struct job *job;
	struct tracer tr;
	pthread_t thread;
	struct smp *cells;  /* method 1: the tile and its left column and upper row */
	struct m2cache m2;
	struct pow_memo memo;
};

static void set_compare(const struct render_opts *o, struct pow_memo *m, struct smp *s)
{
	double e = o->aa_exponent, ch[3] = {s->c.r, s->c.g, s->c.b};
	for (int k = 0; k < 3; k++) {
		if (e == 1) {
			s->g[k] = ch[k];
		} else if (ch[k] == m->in[k]) {
			s->g[k] = m->out[k];
		} else {
			m->in[k] = ch[k];
			s->g[k] = m->out[k] = pow(fmax(ch[k], 0), e);
		}
	}
	s->g[3] = o->alpha ? 1 - s->alpha : 0;
}

/* The sample at image position (x, y), for sample `sample` of pixel
 * (px, py) (the hash inputs of what the camera chooses at random), with
 * its comparison values if `compare` (method 1's supersamples are only
 * averaged, never compared). */
static struct smp take(struct worker *w, double x, double y, int px, int py, uint32_t sample, bool compare)
{
	const struct render_opts *o = w->job->o;
	bool any;
	w->tr.camera_transmit = 0;
	w->tr.camera_rays = 0;
	struct smp s = {.c = camera_sample(&w->tr, x, y, o->width, o->height, px, py, sample, &any)};
	/* The mean transmit of the camera's rays; where the camera has no ray
	 * (outside a fisheye's circle) the pixel is transparent, as in POV-Ray. */
	s.alpha = w->tr.camera_rays ? 1 - w->tr.camera_transmit / w->tr.camera_rays : 0;
	if (compare)
		set_compare(o, &w->memo, &s);
	w->tr.stats.samples++;
	return s;
}

static double difference(const double *a, const double *b)
{
	return fabs(a[0] - b[0]) + fabs(a[1] - b[1]) + fabs(a[2] - b[2]) + fabs(a[3] - b[3]);
}

static void put(struct job *j, int x, int y, const struct smp *s)
{
	float *px = fb_pixel(j->fb, x, y);
	px[0] = (float)s->c.r;
	px[1] = (float)s->c.g;
	px[2] = (float)s->c.b;
	/* With +UA the background is transparent, as in POV-Ray: alpha is
	 * 1 - transmit, but never below the grey of the colour (measured: a
	 * highlight on a clear surface makes it as opaque as it is bright). The
	 * colour is what shows over black (associated alpha). */
	double a = fmax(s->alpha, 0.297 * s->c.r + 0.589 * s->c.g + 0.114 * s->c.b);
	px[3] = (float)(a < 0 ? 0 : a > 1 ? 1 : a);
}

/* A jitter offset in (-amount/2, amount/2) of a cell `cell` wide. */
static double jitter(const struct render_opts *o, uint32_t a, uint32_t b, uint32_t sample, uint32_t purpose,
                     double cell)
{
	if (o->jitter <= 0)
		return 0;
	return o->jitter * (hash_uniform(a, b, sample, purpose) - 0.5) * cell;
}

/* Method 1: replace cell s of pixel (x, y) by the mean of its centre
 * sample and depth x depth samples over the pixel. */
static void supersample(struct worker *w, struct smp *s, int x, int y)
{
	const struct render_opts *o = w->job->o;
	int n = o->aa_depth;
	double cell = 1.0 / n;
	rgb sum = s->c;
	double alpha = s->alpha;
	for (int j = 0; j < n; j++)
		for (int i = 0; i < n; i++) {
			uint32_t k = (uint32_t)(1 + j * n + i);
			double sx = x + (i + 0.5) * cell + jitter(o, (uint32_t)x, (uint32_t)y, k, JITTER_X, cell);
			double sy = y + (j + 0.5) * cell + jitter(o, (uint32_t)x, (uint32_t)y, k, JITTER_Y, cell);
			struct smp t = take(w, sx, sy, x, y, k, false);
			sum = rgb_add(sum, t.c);
			alpha += t.alpha;
		}
	double inv = 1.0 / (n * n + 1);
	s->c = rgb_scale(sum, inv);
	s->alpha = alpha * inv;
	set_compare(o, &w->memo, s);
	s->super = true;
	w->tr.stats.aa_pixels++;
}

static void tile_method1(struct worker *w, int x0, int y0, int x1, int y1)
{
	struct job *j = w->job;
	double thr = j->o->aa_threshold;
	int ex0 = x0 > 0 ? x0 - 1 : x0, ey0 = y0 > 0 ? y0 - 1 : y0;
	int stride = x1 - ex0;
	struct smp *cells = w->cells;
	for (int y = ey0; y < y1; y++)
		for (int x = ex0; x < x1; x++) {
			cells[(y - ey0) * stride + (x - ex0)] = take(w, x + 0.5, y + 0.5, x, y, 0, true);
			cells[(y - ey0) * stride + (x - ex0)].super = false;
		}
	for (int y = y0; y < y1; y++)
		for (int x = x0; x < x1; x++) {
			struct smp *s = &cells[(y - ey0) * stride + (x - ex0)];
			double g[4] = {s->g[0], s->g[1], s->g[2], s->g[3]};
			/* The neighbours' current colours (supersampled or not)
			 * against this pixel's centre sample. A neighbour outside
			 * the block is never supersampled: its block is done. */
			if (x > ex0) {
				struct smp *l = s - 1;
				if (difference(g, l->g) >= thr) {
					if (!l->super && x - 1 >= x0)
						supersample(w, l, x - 1, y);
					if (!s->super)
						supersample(w, s, x, y);
				}
			}
			if (y > ey0) {
				struct smp *u = s - stride;
				if (difference(g, u->g) >= thr) {
					if (!u->super && y - 1 >= y0)
						supersample(w, u, x, y - 1);
					if (!s->super)
						supersample(w, s, x, y);
				}
			}
		}
	for (int y = y0; y < y1; y++)
		for (int x = x0; x < x1; x++)
			put(j, x, y, &cells[(y - ey0) * stride + (x - ex0)]);
}

/* Method 2: the sample at fine-grid point (i, j) of pixel (px, py) (0 to n
 * along each side), from the caches. Its position and jitter depend only
 * on the point, so neighbouring pixels that share it see the same one.
 * Jitter keeps every sample inside its pixel, as POV-Ray 3.7's does
 * (measured on gradients whose colour is the image position, 128x128,
 * +A0.0: with +R1 the pixels are exact, so the corners never move; the
 * spread of the pixels at +R2, +R3 and +R4 is that of offsets of up to a
 * quarter of the fine cell, times the amount, along the pixel's edge for a
 * sample on it and in x and y inside): a jittered corner made corners
 * differ more than POV-Ray's and so subdivided more pixels. */
static const struct smp *m2_sample(struct worker *w, int x0, int y0, int px, int py, int i, int j)
{
	const struct render_opts *o = w->job->o;
	struct m2cache *m = &w->m2;
	int n = m->n;
	struct smp *s;
	if (i % n == 0 && j % n == 0) {
		int k = (py - y0 + j / n) * (TILE + 1) + (px - x0 + i / n);
		if (m->corner_stamp[k] == m->tile_stamp)
			return &m->corner[k];
		m->corner_stamp[k] = m->tile_stamp;
		s = &m->corner[k];
	} else {
		int k = j * (n + 1) + i;
		if (m->inner_stamp[k] == m->pixel_stamp)
			return &m->inner[k];
		m->inner_stamp[k] = m->pixel_stamp;
		s = &m->inner[k];
	}
	uint32_t gx = (uint32_t)px * (uint32_t)n + (uint32_t)i, gy = (uint32_t)py * (uint32_t)n + (uint32_t)j;
	double cell = 1.0 / n;
	double sx = gx * cell + (i % n ? jitter(o, gx, gy, 0, JITTER_X, cell / 2) : 0);
	double sy = gy * cell + (j % n ? jitter(o, gx, gy, 0, JITTER_Y, cell / 2) : 0);
	*s = take(w, sx, sy, (int)gx, (int)gy, 0, true);
	return s;
}

/* The mean colour over the square with corner (i, j) and side `side` (in
 * fine-grid steps) of pixel (px, py), subdivided `level` times so far. */
static struct smp m2_square(struct worker *w, int x0, int y0, int px, int py, int i, int j, int side, int level)
{
	const struct render_opts *o = w->job->o;
	const struct smp *c[4] = {
		m2_sample(w, x0, y0, px, py, i, j), m2_sample(w, x0, y0, px, py, i + side, j),
		m2_sample(w, x0, y0, px, py, i, j + side), m2_sample(w, x0, y0, px, py, i + side, j + side),
	};
	bool split = false;
	if (level < o->aa_depth - 1)
		for (int a = 0; a < 4 && !split; a++)
			for (int b = a + 1; b < 4 && !split; b++)
				split = difference(c[a]->g, c[b]->g) >= o->aa_threshold;
	struct smp r = {.c = rgb_make(0, 0, 0)};
	if (split) {
		int h = side / 2;
		struct smp q[4] = {
			m2_square(w, x0, y0, px, py, i, j, h, level + 1), m2_square(w, x0, y0, px, py, i + h, j, h, level + 1),
			m2_square(w, x0, y0, px, py, i, j + h, h, level + 1),
			m2_square(w, x0, y0, px, py, i + h, j + h, h, level + 1),
		};
		for (int k = 0; k < 4; k++) {
			r.c = rgb_add(r.c, q[k].c);
			r.alpha += q[k].alpha;
		}
	} else {
		for (int k = 0; k < 4; k++) {
			r.c = rgb_add(r.c, c[k]->c);
			r.alpha += c[k]->alpha;
		}
	}
	r.c = rgb_scale(r.c, 0.25);
	r.alpha *= 0.25;
	if (level == 0 && split)
		w->tr.stats.aa_pixels++;
	return r;
}

static void tile_method2(struct worker *w, int x0, int y0, int x1, int y1)
{
	struct m2cache *m = &w->m2;
	m->tile_stamp++;
	for (int y = y0; y < y1; y++)
		for (int x = x0; x < x1; x++) {
			m->pixel_stamp++;
			struct smp s = m2_square(w, x0, y0, x, y, 0, 0, m->n, 0);
			put(w->job, x, y, &s);
		}
}

static void render_tile(struct worker *w, int tile)
{
	struct job *j = w->job;
	const struct render_opts *o = j->o;
	int tx = tile % j->tiles_x, ty = tile / j->tiles_x;
	int x0 = o->col0 + tx * TILE, y0 = o->row0 + ty * TILE;
	int x1 = x0 + TILE < o->col1 ? x0 + TILE : o->col1;
	int y1 = y0 + TILE < o->row1 ? y0 + TILE : o->row1;
	w->tr.stats.pixels += (uint64_t)(x1 - x0) * (uint64_t)(y1 - y0);
	if (o->aa_method == 1) {
		tile_method1(w, x0, y0, x1, y1);
		return;
	}
	if (o->aa_method == 2) {
		tile_method2(w, x0, y0, x1, y1);
		return;
	}
	for (int y = y0; y < y1; y++)
		for (int x = x0; x < x1; x++) {
			struct smp s = take(w, x + 0.5, y + 0.5, x, y, 0, false);
			put(j, x, y, &s);
		}
}

static void worker_scratch(struct worker *w, const struct render_opts *o)
{
	if (o->aa_method == 1) {
		w->cells = calloc((size_t)(TILE + 1) * (TILE + 1), sizeof *w->cells);
		if (!w->cells) abort();
	} else if (o->aa_method == 2) {
		struct m2cache *m = &w->m2;
		m->n = 1 << (o->aa_depth - 1);
		size_t nc = (size_t)(TILE + 1) * (TILE + 1), ni = (size_t)(m->n + 1) * (m->n + 1);
		m->corner = calloc(nc, sizeof *m->corner);
		m->corner_stamp = calloc(nc, sizeof *m->corner_stamp);
		m->inner = calloc(ni, sizeof *m->inner);
		m->inner_stamp = calloc(ni, sizeof *m->inner_stamp);
		if (!m->corner || !m->corner_stamp || !m->inner || !m->inner_stamp) abort();
	}
}

static void worker_scratch_free(struct worker *w)
{
	free(w->cells);
	free(w->m2.corner);
	free(w->m2.corner_stamp);
	free(w->m2.inner);
	free(w->m2.inner_stamp);
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
		w[i].tr.stop = o->stop;
		worker_scratch(&w[i], o);
		for (int k = 0; k < 3; k++)
			w[i].memo.in[k] = NAN; /* equal to no colour */
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
		worker_scratch_free(&w[i]);
	}
	free(w);
	return !atomic_load(&j.stopped) && atomic_load(&j.done) == j.ntiles;
}

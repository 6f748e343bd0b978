/* image.c: images for image_map, bump_map, image_pattern and material_map
 * (see image.h): reading and decoding them once, and looking them up as
 * POV-Ray 3.7 does. The rules below were measured with POV-Ray 3.7.0.10
 * (function { pigment { image_map {...} } } evaluated with #debug); the
 * measurements are recorded in tests/unit/test_image.c. */
#include "image/image.h"

#include "image/formats.h"
#include "image/oiio.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- reading and the cache ---- */

/* The cache: every image alive, found by (path, gamma, premultiplied).
 * Process-wide because an image is a file's content, the same for every
 * scene; the mutex lets scenes load in parallel. */
static pthread_mutex_t cache_lock = PTHREAD_MUTEX_INITIALIZER;
static struct image *cache;

static double srgb_decode(double v)
{
	return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

enum transfer { TF_LINEAR, TF_SRGB, TF_POWER };

/* How POV-Ray 3.7 decodes a file it is given no gamma for. */
static enum transfer file_transfer(const struct oiio_image *o, double *power)
{
	const char *f = o->format;
	if (o->is_float || !strcmp(f, "openexr") || !strcmp(f, "hdr"))
		return TF_LINEAR;
	/* PPM, PGM and TIFF values are taken as they are stored. */
	if (!strcmp(f, "pnm") || !strcmp(f, "tiff"))
		return TF_LINEAR;
	if (!strcmp(f, "png") && o->file_gamma > 0) {
		*power = o->file_gamma;
		return fabs(o->file_gamma - 1) < 1e-6 ? TF_LINEAR : TF_POWER;
	}
	return TF_SRGB;
}

/* Does the format store associated (premultiplied) alpha? */
static bool format_associated(const char *f)
{
	return !strcmp(f, "openexr") || !strcmp(f, "tiff");
}

/* Expand the file's channels to r g b a, straight alpha, decoding colour
 * with tf (alpha is never decoded). */
static void expand(const struct oiio_image *o, float *dst, enum transfer tf, double power, bool associated)
{
	size_t n = (size_t)o->width * o->height;
	int ch = o->channels;
	bool grey = ch <= 2, alpha = ch == 2 || ch == 4;
	for (size_t i = 0; i < n; i++) {
		const float *s = &o->px[i * ch];
		float c[4];
		c[0] = s[0];
		c[1] = grey ? s[0] : s[1];
		c[2] = grey ? s[0] : s[2];
		c[3] = alpha ? s[ch - 1] : 1.0f;
		if (associated && alpha && c[3] > 0)
			for (int k = 0; k < 3; k++)
				c[k] /= c[3];
		for (int k = 0; k < 3; k++) {
			if (tf == TF_SRGB)
				c[k] = (float)srgb_decode(c[k]);
			else if (tf == TF_POWER)
				c[k] = c[k] > 0 ? (float)pow(c[k], power) : c[k];
		}
		memcpy(&dst[i * 4], c, sizeof c);
	}
}

static struct image *build(const char *path, double gamma, int premultiplied, double working, char *err, unsigned errsize)
{
	/* PNG is read by lucent itself (the same samples as the module gives,
	 * formats.h), so a scene with PNG maps does not load OpenImageIO. */
	struct oiio_image o;
	int rc = img_is_png(path) ? img_png_read(path, &o, err, errsize) : oiio_read(path, &o, err, errsize);
	if (rc != 0)
		return NULL;
	struct image *img = calloc(1, sizeof *img);
	size_t n = (size_t)o.width * o.height;
	char *pathcopy = strdup(path);
	float *px = malloc(n * 4 * sizeof(float));
	unsigned char *index = o.index ? o.index : malloc(n);
	if (!img || !pathcopy || !px || !index) {
		free(img); free(pathcopy); free(px); free(index); free(o.px);
		snprintf(err, errsize, "out of memory reading image '%s'", path);
		return NULL;
	}
	img->refs = 1;
	img->path = pathcopy;
	img->width = o.width;
	img->height = o.height;
	img->channels = o.channels;
	img->has_alpha = o.channels == 2 || o.channels == 4;
	img->gamma = gamma;
	img->premultiplied = premultiplied;
	img->working = working;
	img->palette_size = o.index ? o.palette_size : 0;

	bool associated = premultiplied < 0 ? format_associated(o.format) : premultiplied == 1;
	double power = 1;
	enum transfer tf = gamma > 0 ? TF_POWER : gamma < 0 ? TF_SRGB : file_transfer(&o, &power);
	if (gamma > 0)
		power = gamma;
	if (tf == TF_POWER && fabs(power - 1) < 1e-12)
		tf = TF_LINEAR;
	expand(&o, px, tf, power, associated);
	if (working != 1)
		for (size_t i = 0; i < n; i++)
			for (int k = 0; k < 3; k++) {
				float *c = &px[i * 4 + k];
				*c = *c > 0 ? (float)pow(*c, 1 / working) : *c;
			}
	img->px = px;
	/* image_pattern and bump_map read the stored values unless a gamma is
	 * given (then both decode alike). */
	if (gamma == 0 && tf != TF_LINEAR) {
		img->raw = malloc(n * 4 * sizeof(float));
		if (img->raw)
			expand(&o, img->raw, TF_LINEAR, 1, associated);
	}
	if (!o.index) {
		/* Without a palette the index is the stored red value (0..255). */
		int ch = o.channels;
		for (size_t i = 0; i < n; i++) {
			double r = o.px[i * ch];
			r = r < 0 ? 0 : r > 1 ? 1 : r;
			index[i] = (unsigned char)(r * 255 + 0.5);
		}
	}
	img->index = index;
	free(o.px);
	return img;
}

struct image *image_load_working(const char *path, double gamma, int premultiplied, double working, char *err,
                                 unsigned errsize)
{
	pthread_mutex_lock(&cache_lock);
	for (struct image *i = cache; i; i = i->next) {
		if (!strcmp(i->path, path) && i->gamma == gamma && i->premultiplied == premultiplied &&
		    i->working == working) {
			i->refs++;
			pthread_mutex_unlock(&cache_lock);
			return i;
		}
	}
	struct image *img = build(path, gamma, premultiplied, working, err, errsize);
	if (img) {
		img->next = cache;
		cache = img;
	}
	pthread_mutex_unlock(&cache_lock);
	return img;
}

struct image *image_load_opts(const char *path, double gamma, int premultiplied, char *err, unsigned errsize)
{
	return image_load_working(path, gamma, premultiplied, 1, err, errsize);
}

struct image *image_from_pixels(int width, int height, int channels, float *px)
{
	size_t n = (size_t)width * height;
	struct image *img = calloc(1, sizeof *img);
	unsigned char *index = malloc(n ? n : 1);
	if (!img || !index) {
		free(img); free(index); free(px);
		return NULL;
	}
	img->refs = 1;
	img->width = width;
	img->height = height;
	img->channels = channels;
	img->has_alpha = channels == 2 || channels == 4;
	img->premultiplied = 0;
	img->working = 1;
	img->px = px;
	for (size_t i = 0; i < n; i++) {
		double r = px[i * 4];
		r = r < 0 ? 0 : r > 1 ? 1 : r;
		index[i] = (unsigned char)(r * 255 + 0.5);
	}
	img->index = index;
	return img;
}

bool image_mapping_to_working(struct image_mapping *m, double working, char *err, unsigned errsize)
{
	if (!m->img || !m->img->path || working == m->img->working)
		return true;
	struct image *w = image_load_working(m->img->path, m->img->gamma, m->img->premultiplied, working, err, errsize);
	if (!w)
		return false;
	image_unref(m->img);
	m->img = w;
	return true;
}

struct image *image_load(const char *path, double gamma, char *err, unsigned errsize)
{
	return image_load_opts(path, gamma, -1, err, errsize);
}

struct image *image_ref(struct image *img)
{
	if (img) {
		pthread_mutex_lock(&cache_lock);
		img->refs++;
		pthread_mutex_unlock(&cache_lock);
	}
	return img;
}

void image_unref(struct image *img)
{
	if (!img)
		return;
	pthread_mutex_lock(&cache_lock);
	bool last = --img->refs == 0;
	if (last)
		for (struct image **pp = &cache; *pp; pp = &(*pp)->next)
			if (*pp == img) {
				*pp = img->next;
				break;
			}
	pthread_mutex_unlock(&cache_lock);
	if (!last)
		return;
	free((void *)img->path);
	free(img->px);
	free(img->raw);
	free(img->index);
	free(img);
}

/* ---- laying the image on space ---- */

static double angle_u(double x, double z)
{
	double u = atan2(z, x) / (2 * M_PI);
	return u < 0 ? u + 1 : u;
}

/* map_type 0: the unit square of the x-y plane, repeated (pixel column
 * floor(u * width), row from the bottom floor(v * height)).
 * 1: spherical about the origin: u = atan2(z, x) / 2pi from +x towards +z,
 * v = 0.5 + asin(y / |q|) / pi. 2: cylindrical about the y axis: u as for
 * the sphere, v = y. 5: a torus of major radius 1 in the x-z plane: u as
 * for the sphere, v = 0.5 + atan2(y, r - 1) / 2pi (0.5 on the outer
 * equator, 0.75 on top). `once` leaves everything outside u, v in [0, 1]
 * uncovered; both ends count as inside and wrap to 0. */
bool image_map_uv(const struct image_mapping *m, vec3 q, double *u, double *v)
{
	double x = q.x, y = q.y;
	switch (m->map_type) {
	case 1: {
		double len = sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
		if (len == 0)
			return false;
		x = angle_u(q.x, q.z);
		double s = q.y / len;
		y = 0.5 + asin(s > 1 ? 1 : s < -1 ? -1 : s) / M_PI;
		break;
	}
	case 2: {
		if (q.x == 0 && q.z == 0)
			return false;
		x = angle_u(q.x, q.z);
		break;
	}
	case 5: {
		double r = sqrt(q.x * q.x + q.z * q.z);
		if (r == 0)
			return false;
		double major = m->major_radius > 0 ? m->major_radius : 1;
		x = angle_u(q.x, q.z);
		y = 0.5 + atan2(q.y, r - major) / (2 * M_PI);
		break;
	}
	default:
		break;
	}
	if (m->once && (x < 0 || x > 1 || y < 0 || y > 1))
		return false;
	x -= floor(x);
	y -= floor(y);
	*u = x >= 1 ? 0 : x;
	*v = y >= 1 ? 0 : y;
	return true;
}

/* A column or row index: wrapped around the image, or clamped to its edge
 * under `once`. */
static int fix(int i, int n, bool once)
{
	if (once)
		return i < 0 ? 0 : i >= n ? n - 1 : i;
	i %= n;
	return i < 0 ? i + n : i;
}

/* What one pixel (column x, row y from the top) gives: r g b f t. With
 * data, the stored values (no decoding) and the alpha in the alpha slot
 * (f unused). */
static void pixel(const struct image_mapping *m, int x, int y, bool data, double out[5])
{
	const struct image *img = m->img;
	size_t i = (size_t)y * img->width + x;
	const float *s = &(data && img->raw ? img->raw : img->px)[i * 4];
	out[0] = s[0];
	out[1] = s[1];
	out[2] = s[2];
	if (data) {
		out[3] = s[3];
		out[4] = 0;
		return;
	}
	double a = s[3];
	if (img->palette_size > 0) {
		/* Paletted: POV-Ray keeps filter and transmit per palette entry;
		 * `filter/transmit all` set every entry, then the per-entry ones
		 * (m->entry, in the order written) set theirs; transmit defaults
		 * to the entry's alpha. */
		int idx = img->index[i];
		double f = m->has_filter_all ? m->filter_all : 0;
		double t = m->has_transmit_all ? m->transmit_all : 1 - a;
		for (int k = 0; k < m->nentry; k++) {
			if (m->entry[k].index != idx)
				continue;
			if (m->entry[k].has_filter)
				f = m->entry[k].filter;
			if (m->entry[k].has_transmit)
				t = m->entry[k].transmit;
		}
		out[3] = f;
		out[4] = t;
	} else {
		/* Without a palette `transmit all` adds to the alpha's. */
		out[3] = m->has_filter_all ? m->filter_all : 0;
		out[4] = (m->has_transmit_all ? m->transmit_all : 0) + (img->has_alpha ? 1 - a : 0);
	}
}

/* Catmull-Rom through p0..p3 at t in [0, 1] between p1 and p2. */
static double cubic(double p0, double p1, double p2, double p3, double t)
{
	return 0.5 * (2 * p1 + (p2 - p0) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t * t +
	              (3 * p1 - p0 - 3 * p2 + p3) * t * t * t);
}

/* The 5 values at (u, v) with m's interpolation. Pixel centres are at
 * ((x + 0.5) / width, 1 - (y + 0.5) / height); interpolation uses the
 * 2x2 (4x4 for bicubic) pixels around the point, wrapping around the
 * image, or clamped to its edges under `once`. Interpolate 4 weighs the
 * four by the inverse square of their distance in pixels (a point on a
 * centre takes that pixel). */
static void lookup(const struct image_mapping *m, double u, double v, bool data, double out[5])
{
	const struct image *img = m->img;
	int w = img->width, h = img->height;
	if (m->interpolate != 2 && m->interpolate != 3 && m->interpolate != 4) {
		int x = (int)(u * w), yb = (int)(v * h);
		pixel(m, x >= w ? w - 1 : x, h - 1 - (yb >= h ? h - 1 : yb), data, out);
		return;
	}
	double xr = u * w - 0.5, yr = (1 - v) * h - 0.5;
	double fx0 = floor(xr), fy0 = floor(yr);
	double tx = xr - fx0, ty = yr - fy0;
	int x0 = (int)fx0, y0 = (int)fy0;
	bool once = m->once;
	double p[4][4][5];
	if (m->interpolate == 3) {
		for (int j = 0; j < 4; j++)
			for (int i = 0; i < 4; i++)
				pixel(m, fix(x0 - 1 + i, w, once), fix(y0 - 1 + j, h, once), data, p[j][i]);
		for (int c = 0; c < 5; c++) {
			double row[4];
			for (int j = 0; j < 4; j++)
				row[j] = cubic(p[j][0][c], p[j][1][c], p[j][2][c], p[j][3][c], tx);
			out[c] = cubic(row[0], row[1], row[2], row[3], ty);
		}
		return;
	}
	for (int j = 0; j < 2; j++)
		for (int i = 0; i < 2; i++)
			pixel(m, fix(x0 + i, w, once), fix(y0 + j, h, once), data, p[j][i]);
	double wt[2][2];
	if (m->interpolate == 2) {
		wt[0][0] = (1 - tx) * (1 - ty);
		wt[0][1] = tx * (1 - ty);
		wt[1][0] = (1 - tx) * ty;
		wt[1][1] = tx * ty;
	} else {
		double sum = 0;
		for (int j = 0; j < 2; j++)
			for (int i = 0; i < 2; i++) {
				double dx = i ? 1 - tx : tx, dy = j ? 1 - ty : ty, d2 = dx * dx + dy * dy;
				if (d2 == 0) {
					memcpy(out, p[j][i], sizeof p[j][i]);
					return;
				}
				wt[j][i] = 1 / d2;
				sum += wt[j][i];
			}
		for (int j = 0; j < 2; j++)
			for (int i = 0; i < 2; i++)
				wt[j][i] /= sum;
	}
	for (int c = 0; c < 5; c++)
		out[c] = wt[0][0] * p[0][0][c] + wt[0][1] * p[0][1][c] + wt[1][0] * p[1][0][c] + wt[1][1] * p[1][1][c];
}

bool image_map_eval(const struct image_mapping *m, vec3 q, struct rgbft *out, int *index)
{
	double u, v;
	if (!m->img || !image_map_uv(m, q, &u, &v)) {
		*out = (struct rgbft){1, 1, 1, 0, 1};
		if (index)
			*index = 0;
		return false;
	}
	double c[5];
	lookup(m, u, v, false, c);
	*out = (struct rgbft){c[0], c[1], c[2], c[3], c[4]};
	if (index) {
		const struct image *img = m->img;
		int x = (int)(u * img->width), yb = (int)(v * img->height);
		if (x >= img->width) x = img->width - 1;
		if (yb >= img->height) yb = img->height - 1;
		*index = img->index[(size_t)(img->height - 1 - yb) * img->width + x];
	}
	return true;
}

double image_map_value(const struct image_mapping *m, vec3 q)
{
	double u, v;
	if (!m->img || !image_map_uv(m, q, &u, &v))
		return 0;
	const struct image *img = m->img;
	double value;
	if (m->use_index && !m->use_color && img->palette_size > 0) {
		int x = (int)(u * img->width), yb = (int)(v * img->height);
		if (x >= img->width) x = img->width - 1;
		if (yb >= img->height) yb = img->height - 1;
		value = img->index[(size_t)(img->height - 1 - yb) * img->width + x] / 255.0;
	} else {
		double c[5];
		lookup(m, u, v, true, c);
		if (m->use_alpha)
			value = img->has_alpha ? 1 - c[3] : c[0];
		else
			value = 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2];
	}
	return value < 0 ? 0 : value > 1 ? 1 : value;
}

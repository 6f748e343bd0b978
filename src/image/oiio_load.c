/* oiio_load.c: load the lucent-oiio.so module on first use and call into
 * it (see oiio.h for why it is a module). */
#include "image/oiio.h"

#include <dlfcn.h>
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef LUCENT_PKGLIB_DIR
#define LUCENT_PKGLIB_DIR "/usr/local/lib/lucent"
#endif
#define MODULE_NAME "lucent-oiio.so"

/* Loaded once per process; the error text of a failed load is kept so that
 * every later call reports it. */
static pthread_once_t once = PTHREAD_ONCE_INIT;
static oiio_write_fn *write_fn;
static oiio_read_fn *read_fn;
static char load_error[PATH_MAX + 256];

static void *try_open(const char *path, char *why, size_t n)
{
	void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
	if (!h && why[0] == 0) {
		const char *e = dlerror();
		snprintf(why, n, "%s", e ? e : path);
	}
	return h;
}

static void load(void)
{
	char why[PATH_MAX + 128] = "";
	void *h = NULL;
	const char *env = getenv("LUCENT_OIIO_MODULE");
	if (env && *env) {
		h = try_open(env, why, sizeof why);
	} else {
		char exe[PATH_MAX], path[PATH_MAX + sizeof MODULE_NAME + 1];
		ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
		if (n > 0) {
			exe[n] = 0;
			char *slash = strrchr(exe, '/');
			if (slash) {
				*slash = 0;
				snprintf(path, sizeof path, "%s/%s", exe, MODULE_NAME);
				if (access(path, R_OK) == 0)
					h = try_open(path, why, sizeof why);
			}
		}
		if (!h)
			h = try_open(LUCENT_PKGLIB_DIR "/" MODULE_NAME, why, sizeof why);
	}
	if (h) {
		write_fn = (oiio_write_fn *)dlsym(h, OIIO_WRITE_SYMBOL);
		read_fn = (oiio_read_fn *)dlsym(h, OIIO_READ_SYMBOL);
	}
	if (!write_fn || !read_fn) {
		write_fn = NULL;
		read_fn = NULL;
		snprintf(load_error, sizeof load_error,
		         "cannot load the image module %s (%s); set LUCENT_OIIO_MODULE to its path",
		         MODULE_NAME, why[0] ? why : "entry point missing");
	}
}

int oiio_write(const char *path, const char *format, int width, int height, int channels, enum oiio_type type,
               const void *pixels, int srgb, char *err, unsigned errsize)
{
	pthread_once(&once, load);
	if (!write_fn) {
		if (err && errsize)
			snprintf(err, errsize, "%s", load_error);
		return 1;
	}
	return write_fn(path, format, width, height, channels, type, pixels, srgb, err, errsize);
}

int oiio_read(const char *path, struct oiio_image *out, char *err, unsigned errsize)
{
	memset(out, 0, sizeof *out);
	pthread_once(&once, load);
	if (!read_fn) {
		if (err && errsize)
			snprintf(err, errsize, "%s", load_error);
		return 1;
	}
	return read_fn(path, out, err, errsize);
}

/* main.c: the lucent command: options, then parse → prepare → render →
 * write, with timings and statistics. Exit status: 0 done, 1 error,
 * 2 interrupted. */
#include "config.h"
#include "geom/shapes2.h"

#include "image/framebuffer.h"
#include "image/output.h"
#include "lang/diag.h"
#include "lang/parse.h"
#include "lang/source.h"
#include "options.h"
#include "render/prepare.h"
#include "render/render.h"
#include "scene/fn.h"
#include "scene/scene.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#ifndef LUCENT_STDLIB_DIR
#define LUCENT_STDLIB_DIR "/usr/local/share/lucent"
#endif

/* The one piece of process-wide state: set by SIGINT/SIGTERM, read by the
 * render threads between tiles, by the function VM's sum() and prod()
 * loops, and by the writer before it renames. */
static volatile sig_atomic_t interrupted;

static void on_signal(int sig)
{
	(void)sig;
	interrupted = 1;
}

static double now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static int core_count(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);
	return n > 0 ? (int)n : 1;
}

static bool is_dir(const char *p)
{
	struct stat st;
	return p && stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}

/* The default output name: the scene's path with the format's extension
 * (POV-Ray's rule); "stdin.<ext>" when reading standard input. */
static char *default_output(const char *input, enum img_format f)
{
	const char *ext = img_format_ext(f);
	const char *base = strcmp(input, "-") == 0 ? "stdin" : input;
	const char *slash = strrchr(base, '/');
	const char *dot = strrchr(base, '.');
	size_t stem = dot && (!slash || dot > slash) ? (size_t)(dot - base) : strlen(base);
	char *out = malloc(stem + strlen(ext) + 2);
	if (!out) abort();
	sprintf(out, "%.*s.%s", (int)stem, base, ext);
	return out;
}

/* features: what the render simulated; possible: what the scene could
 * show at full quality (the rest of it was left out by +Q). */
static void print_stats(FILE *out, const struct stats *st, unsigned features, unsigned possible, int quality,
                        double tparse, double tprep, double trender, int w, int h)
{
	fprintf(out, "Render statistics\n");
	fprintf(out, "  image       %d x %d\n", w, h);
	fprintf(out, "  parse       %.3f s\n", tparse);
	fprintf(out, "  prepare     %.3f s\n", tprep);
	fprintf(out, "  render      %.3f s\n", trender);
	fprintf(out, "  pixels      %llu\n", (unsigned long long)st->pixels);
	fprintf(out, "  samples     %llu (%.2f per pixel)\n", (unsigned long long)st->samples,
	        st->pixels ? (double)st->samples / (double)st->pixels : 0.0);
	if (features & FEAT_ANTIALIAS)
		fprintf(out, "  supersampled pixels %llu\n", (unsigned long long)st->aa_pixels);
	unsigned long long total = 0;
	for (int k = 0; k < RAY__COUNT; k++)
		total += st->rays[k];
	fprintf(out, "  rays        %llu\n", total);
	for (int k = 0; k < RAY__COUNT; k++)
		fprintf(out, "    %-10s %llu\n", stats_ray_name((enum ray_kind)k), (unsigned long long)st->rays[k]);
	if (st->rays[RAY_SHADOW])
		fprintf(out, "  shadow rays answered by the last blocker: %llu\n", (unsigned long long)st->shadow_cache_hits);
	fputs("  simulated ", out);
	bool any = false;
	for (int i = 0; i < FEAT__COUNT; i++)
		if (features & (1u << i)) {
			fprintf(out, "%s%s", any ? ", " : " ", feature_name((enum feature)(1u << i)));
			any = true;
		}
	fputs(any ? "\n" : " (none)\n", out);
	if (possible & ~features & ~(unsigned)FEAT_ANTIALIAS) {
		fprintf(out, "  left out  ");
		any = false;
		for (int i = 0; i < FEAT__COUNT; i++)
			if ((possible & ~features) & (1u << i) && (1u << i) != FEAT_ANTIALIAS) {
				fprintf(out, "%s%s", any ? ", " : " ", feature_name((enum feature)(1u << i)));
				any = true;
			}
		fprintf(out, " (quality +Q%d)\n", quality);
	}
	fputs("  skipped   ", out);
	any = false;
	for (int i = 0; i < FEAT__COUNT; i++)
		if (!(features & (1u << i)) && !(possible & (1u << i)) && (1u << i) != FEAT_ANTIALIAS) {
			fprintf(out, "%s%s", any ? ", " : " ", feature_name((enum feature)(1u << i)));
			any = true;
		}
	fputs(any ? " (the scene cannot show them)\n" : " (none)\n", out);
}

/* lucent --regress ARGS: run lucent-regress ARGS (doc/regress.md), the
 * script installed beside lucent, with LUCENT naming this program: from
 * argv[0]'s folder when it has one, else through PATH. Returns only on
 * failure. */
/* POV-Ray's warnings after the render about each isosurface (in o and
 * below it) whose searches met a gradient above its max_gradient (it may
 * have holes) or more than 0.5 below it (it renders slower than it could;
 * measured: 0.327 found against 0.85 given warns, about 0.33 against 0.8
 * does not, 0.739 against 1.3 and 2.287 against 3 warn). */
static void warn_gradients(struct diag *d, struct object *o)
{
	double found, given;
	if (isosurface_gradient_report(o, &found, &given)) {
		if (found > given)
			diag_report(d, DIAG_WARNING, o->pos,
			            "the largest gradient found was %.3f, but max_gradient of the isosurface is %.3f: "
			            "it may have holes; raise max_gradient", found, given);
		else if (found > 0 && given - found > 0.5)
			diag_report(d, DIAG_WARNING, o->pos,
			            "the largest gradient found was %.3f, but max_gradient of the isosurface is %.3f: "
			            "lower max_gradient to render it faster", found, given);
	}
	struct object **kids;
	size_t n = o->ops->children ? o->ops->children(o, &kids) : 0;
	for (size_t i = 0; i < n; i++)
		warn_gradients(d, kids[i]);
}

static int run_regress(char **argv)
{
	static char path[4096];
	const char *slash = strrchr(argv[0], '/');
	if (slash) {
		snprintf(path, sizeof path, "%.*s/lucent-regress", (int)(slash - argv[0]), argv[0]);
		setenv("LUCENT", argv[0], 1);
	} else {
		snprintf(path, sizeof path, "lucent-regress");
	}
	argv[1] = path;
	execvp(path, argv + 1);
	fprintf(stderr, "lucent: error: cannot run %s: %s\n", path, strerror(errno));
	return 1;
}

int main(int argc, char **argv)
{
	if (argc > 1 && strcmp(argv[1], "--regress") == 0)
		return run_regress(argv);

	struct options opt;
	options_init(&opt);
	int status = 1;
	struct srcmgr *sm = NULL;
	struct scene *scene = NULL;
	struct prepared *prep = NULL;
	struct framebuffer *fb = NULL;

	if (options_parse(&opt, argc, argv, stderr) != 0)
		goto done;
	if (opt.help) {
		options_usage(stdout);
		status = 0;
		goto done;
	}
	if (opt.version) {
		printf("lucent %s\n", PACKAGE_VERSION);
		status = 0;
		goto done;
	}
	if (!opt.input) {
		fprintf(stderr, "lucent: error: no scene file given (see lucent --help)\n");
		goto done;
	}
	if (opt.output) {
		/* As POV-Ray: a name without an extension gets the format's. */
		const char *slash = strrchr(opt.output, '/');
		const char *dot = strrchr(opt.output, '.');
		if (!dot || (slash && dot < slash)) {
			char *named = malloc(strlen(opt.output) + 8);
			if (!named) abort();
			sprintf(named, "%s.%s", opt.output, img_format_ext(opt.format));
			free(opt.output);
			opt.output = named;
		} else if (!opt.format_set && !img_format_from_path(opt.output, &opt.format)) {
			fprintf(stderr, "lucent: error: unknown image type '%s' in '%s' "
			        "(use .png .exr .hdr .tga .ppm .jpg .tif, or +F to choose the format)\n",
			        dot, opt.output);
			goto done;
		}
	} else {
		opt.output = default_output(opt.input, opt.format);
	}

	/* The image's size is known before anything is parsed. */
	double pixels = (double)opt.width * (double)opt.height;
	if (pixels > opt.max_image) {
		fprintf(stderr, "lucent: error: a %dx%d image has more than %.0f pixels (lucent --limit image-size=N "
		        "raises the limit)\n", opt.width, opt.height, opt.max_image);
		goto done;
	}
	if (!parse_memory_ok((size_t)pixels, 4 * sizeof(float))) {
		fprintf(stderr, "lucent: error: a %dx%d image needs more memory than the machine has\n", opt.width,
		        opt.height);
		goto done;
	}

	struct sigaction sa;
	memset(&sa, 0, sizeof sa);
	sa.sa_handler = on_signal;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);
	fn_set_stop(&interrupted);

	const char *stdlib_dir = getenv("LUCENT_STDLIB");
	if (!stdlib_dir || !*stdlib_dir)
		stdlib_dir = LUCENT_STDLIB_DIR;
	if (!is_dir(stdlib_dir))
		stdlib_dir = NULL;

	FILE *debug_out = stderr;
	if (opt.debug_file) {
		debug_out = fopen(opt.debug_file, "w");
		if (!debug_out) {
			fprintf(stderr, "lucent: error: cannot write debug file '%s': %s\n", opt.debug_file, strerror(errno));
			goto done;
		}
	}
	sm = src_new();
	struct diag diag;
	diag_init(&diag, sm, stderr);
	scene = scene_new();
	struct parse_opts po = {
		.input = opt.input,
		.lib_paths = (const char *const *)opt.lib_paths,
		.nlib_paths = opt.nlib_paths,
		.stdlib_dir = stdlib_dir,
		.defines = opt.defines,
		.ndefines = opt.ndefines,
		.image_width = opt.width,
		.image_height = opt.height,
		.clock = opt.clock,
		.debug_out = debug_out,
		.io_unrestricted = opt.io_unrestricted,
		.stop = &interrupted,
		.limits = opt.limits,
	};
	double t0 = now();
	int prc = parse_scene(sm, &diag, &po, scene);
	if (debug_out != stderr)
		fclose(debug_out);
	if (prc == 2) {
		status = 2;
		goto done;
	}
	if (prc != 0)
		goto done;
	if (interrupted) {
		fprintf(stderr, "lucent: interrupted while parsing\n");
		status = 2;
		goto done;
	}
	/* POV-Ray 3.7: a 3.7 scene without assumed_gamma works linearly; an
	 * older one, or one that never says #version, gets no gamma handling. */
	double gamma = scene->gs.assumed_gamma;
	if (!scene->gs.assumed_gamma_set && (!scene->version_set || scene->version < 3.7))
		gamma = 0;
	double t1 = now();
	prep = prepare_scene(scene);
	prep->signature = opt.signature;
	unsigned possible = prep->features;
	prepare_quality(prep, opt.quality > 9 ? 9 : opt.quality);
	if (opt.antialias)
		prep->features |= FEAT_ANTIALIAS;
	if (opt.signature)
		prep->features = possible = 0; /* flat colours: no effect is simulated */
	double t2 = now();

	int row0 = opt.start_row >= 0 ? options_bound(opt.start_row, opt.height, false) : 0;
	int row1 = opt.end_row >= 0 ? options_bound(opt.end_row, opt.height, true) : opt.height;
	int col0 = opt.start_col >= 0 ? options_bound(opt.start_col, opt.width, false) : 0;
	int col1 = opt.end_col >= 0 ? options_bound(opt.end_col, opt.width, true) : opt.width;
	if (row0 >= row1 || col0 >= col1) {
		fprintf(stderr, "lucent: error: the partial render region is empty (rows %d-%d, columns %d-%d)\n",
		        row0 + 1, row1, col0 + 1, col1);
		goto done;
	}
	fb = fb_new(opt.width, opt.height);
	if (!fb) {
		fprintf(stderr, "lucent: error: cannot allocate a %dx%d image\n", opt.width, opt.height);
		goto done;
	}
	struct render_opts ro = {
		.width = opt.width, .height = opt.height,
		.row0 = row0, .row1 = row1, .col0 = col0, .col1 = col1,
		.threads = opt.threads > 0 ? opt.threads : core_count(),
		.progress = !opt.quiet && isatty(STDERR_FILENO),
		.stop = &interrupted,
		.aa_method = opt.antialias && !opt.signature ? opt.aa_method : 0,
		.aa_threshold = opt.aa_threshold,
		.aa_depth = opt.aa_depth,
		.jitter = opt.jitter ? opt.jitter_amount : 0,
		/* Colours are compared in linear light raised to 1 / +AG (measured:
		 * doc/rendering.md); a scene without gamma handling works in
		 * linear light. */
		.aa_exponent = (gamma > 0 ? gamma : 1.0) / opt.aa_gamma,
		.alpha = opt.alpha,
	};
	if (opt.verbose && !opt.quiet)
		fprintf(stderr, "lucent: %s: %zu objects (%zu unbounded), %zu lights, %zu BVH nodes; "
		        "rendering rows %d-%d, columns %d-%d of %dx%d on up to %d threads\n",
		        opt.input, scene->nobjects, prep->nunbounded, scene->nlights, bvh_node_count(prep->bvh),
		        row0 + 1, row1, col0 + 1, col1, opt.width, opt.height, ro.threads);
	struct stats st;
	memset(&st, 0, sizeof st);
	bool complete = render_image(prep, &ro, fb, &st);
	double t3 = now();
	if (!complete || interrupted) {
		fprintf(stderr, "lucent: interrupted; no image written\n");
		status = 2;
		goto done;
	}
	for (size_t i = 0; i < scene->nobjects; i++)
		warn_gradients(&diag, scene->objects[i]);
	/* The scene is no longer needed: free it before the image module is
	 * loaded, so that the two never take memory at the same time. */
	unsigned features = prep->features;
	prepared_free(prep);
	prep = NULL;
	scene_free(scene);
	scene = NULL;
	src_free(sm);
	sm = NULL;
	if (opt.output_to_file) {
		struct img_out io = {
			.path = opt.output, .format = opt.format, .bits = opt.bits,
			.alpha = opt.alpha, .rle = opt.tga_rle, .gamma = gamma, .stop = &interrupted,
		};
		char err[1024];
		int rc = img_write(fb, &io, err, sizeof err);
		if (rc == 2) {
			fprintf(stderr, "lucent: interrupted; no image written\n");
			status = 2;
			goto done;
		}
		if (rc != 0) {
			fprintf(stderr, "lucent: error: %s\n", err);
			goto done;
		}
	}
	if (!opt.quiet) {
		print_stats(stderr, &st, features, possible, opt.quality, t1 - t0, t2 - t1, t3 - t2, opt.width, opt.height);
		if (opt.output_to_file)
			fprintf(stderr, "wrote %s\n", opt.output);
	}
	status = 0;
done:
	fb_free(fb);
	prepared_free(prep);
	scene_free(scene);
	src_free(sm);
	options_free(&opt);
	return status;
}

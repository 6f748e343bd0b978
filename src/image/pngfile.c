/* pngfile.c: PNG files through libpng (see formats.h): writing lucent's
 * images and reading image maps. libpng reports errors by longjmp to the
 * setjmp in each entry point; everything those jumps may skip is allocated
 * before the setjmp, so it is freed on both paths. */
#include "image/formats.h"

#include <png.h>

#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

/* libpng's error text, kept for the caller's message. */
struct png_ctx {
	char *err;
	size_t errsize;
};

static void on_error(png_structp png, png_const_charp msg)
{
	struct png_ctx *c = png_get_error_ptr(png);
	if (c && c->err && c->errsize)
		snprintf(c->err, c->errsize, "%s", msg);
	png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp msg)
{
	(void)png;
	(void)msg;
}

int img_png_write(FILE *fp, const struct img_samples *s, char *err, size_t errsize)
{
	size_t rowbytes = (size_t)s->width * (size_t)s->channels * (size_t)(s->bits / 8);
	unsigned char *row = malloc(rowbytes ? rowbytes : 1);
	if (!row) {
		snprintf(err, errsize, "out of memory writing a PNG");
		return 1;
	}
	struct png_ctx ctx = {err, errsize};
	png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &ctx, on_error, on_warning);
	png_infop info = png ? png_create_info_struct(png) : NULL;
	if (!png || !info) {
		png_destroy_write_struct(&png, &info);
		free(row);
		snprintf(err, errsize, "out of memory writing a PNG");
		return 1;
	}
	if (setjmp(png_jmpbuf(png))) {
		png_destroy_write_struct(&png, &info);
		free(row);
		return 1;
	}
	png_init_io(png, fp);
	png_set_IHDR(png, info, (png_uint_32)s->width, (png_uint_32)s->height, s->bits,
	             s->channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
	             PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	/* The chunks OpenImageIO wrote for an sRGB image: gAMA 1/2.2, sRGB
	 * (absolute colorimetric intent) and cHRM. */
	png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
	png_text text = {.compression = PNG_TEXT_COMPRESSION_NONE, .key = "Software", .text = "lucent"};
	png_set_text(png, info, &text, 1);
	png_write_info(png, info);
	size_t per_row = (size_t)s->width * (size_t)s->channels;
	for (int y = 0; y < s->height; y++) {
		if (s->bits == 8) {
			memcpy(row, s->u8 + (size_t)y * per_row, per_row);
		} else {
			/* PNG stores 16-bit samples big-endian. */
			const uint16_t *src = s->u16 + (size_t)y * per_row;
			for (size_t i = 0; i < per_row; i++) {
				row[2 * i] = (unsigned char)(src[i] >> 8);
				row[2 * i + 1] = (unsigned char)src[i];
			}
		}
		png_write_row(png, row);
	}
	png_write_end(png, NULL);
	png_destroy_write_struct(&png, &info);
	free(row);
	return 0;
}

bool img_is_png(const char *path)
{
	FILE *fp = fopen(path, "rb");
	if (!fp)
		return false;
	unsigned char sig[8];
	bool yes = fread(sig, 1, sizeof sig, fp) == sizeof sig && png_sig_cmp(sig, 0, sizeof sig) == 0;
	fclose(fp);
	return yes;
}

/* What img_png_read allocates; all of it is freed on failure. volatile:
 * libpng may longjmp out after these were set. */
struct png_read_state {
	FILE *fp;
	unsigned char *data;      /* the decoded rows */
	unsigned char **rows;
	float *px;
	unsigned char *index;
};

static void read_state_free(struct png_read_state *st)
{
	if (st->fp)
		fclose(st->fp);
	free(st->data);
	free(st->rows);
	free(st->px);
	free(st->index);
}

/* The samples and facts OpenImageIO gives for a PNG (measured against the
 * module on every colour type and bit depth; tests/unit/test_image.c):
 * - grey, grey+alpha, RGB, RGBA as stored; grey of 1, 2 or 4 bits is
 *   scaled to 8 (v * 255 / (2^bits - 1)); samples are v * (1 / 255.0f) or
 *   v * (1 / 65535.0f) in single precision (not v / 255.0f, which differs
 *   in the last bit);
 * - a palette becomes RGB, or RGBA when the file has a tRNS chunk (alpha
 *   of the entries it does not list: 1); the palette's colours are
 *   v / 255.0f (the module takes them from the palette itself);
 * - a tRNS colour key on grey or RGB adds an alpha channel: 0 on pixels
 *   of that colour, 1 elsewhere;
 * - gAMA g gives the decoding gamma 1/g rounded to two decimals
 *   (OpenImageIO's rounding: gAMA 0.45455 gives 2.2, 0.77777 gives 1.29),
 *   unless the file also has an sRGB chunk (then 0: sRGB). */
int img_png_read(const char *path, struct oiio_image *out, char *err, size_t errsize)
{
	memset(out, 0, sizeof *out);
	struct png_read_state st = {0};
	struct png_ctx ctx = {err, errsize};
	st.fp = fopen(path, "rb");
	if (!st.fp) {
		snprintf(err, errsize, "cannot read image '%s': %s", path, strerror(errno));
		return 1;
	}
	png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx, on_error, on_warning);
	png_infop info = png ? png_create_info_struct(png) : NULL;
	if (!png || !info) {
		png_destroy_read_struct(&png, &info, NULL);
		read_state_free(&st);
		snprintf(err, errsize, "out of memory reading image '%s'", path);
		return 1;
	}
	/* st lives in this frame and is only read after a longjmp; its
	 * members are set through a pointer, so they are current. */
	struct png_read_state *volatile sp = &st;
	if (setjmp(png_jmpbuf(png))) {
		png_destroy_read_struct(&png, &info, NULL);
		read_state_free(sp);
		memset(out, 0, sizeof *out);
		return 1;
	}
	png_init_io(png, sp->fp);
	png_read_info(png, info);
	png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
	int depth = png_get_bit_depth(png, info), ctype = png_get_color_type(png, info);
	if (w == 0 || h == 0 || (size_t)w * h > ((size_t)1 << 31) / 16) {
		snprintf(err, errsize, "image '%s' has an unusable size", path);
		png_longjmp(png, 1);
	}
	size_t n = (size_t)w * h;
	bool paletted = ctype == PNG_COLOR_TYPE_PALETTE;
	bool has_trns = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
	png_colorp plte = NULL;
	int nplte = 0;
	png_bytep trns_alpha = NULL;
	int ntrns = 0;
	png_color_16p trns_key = NULL;
	if (paletted) {
		if (!png_get_PLTE(png, info, &plte, &nplte) || nplte == 0)
			png_error(png, "paletted PNG without a palette");
		/* One index per byte. */
		if (depth < 8)
			png_set_packing(png);
		if (has_trns)
			png_get_tRNS(png, info, &trns_alpha, &ntrns, NULL);
	} else {
		if (ctype == PNG_COLOR_TYPE_GRAY && depth < 8)
			png_set_expand_gray_1_2_4_to_8(png);
		if (has_trns)
			png_set_tRNS_to_alpha(png);
		(void)trns_key;
	}
	png_set_interlace_handling(png);
	png_read_update_info(png, info);
	int ch = png_get_channels(png, info);
	int bits = png_get_bit_depth(png, info);
	size_t rowbytes = png_get_rowbytes(png, info);
	sp->data = malloc(rowbytes * h);
	sp->rows = malloc(sizeof *sp->rows * h);
	if (!sp->data || !sp->rows) {
		snprintf(err, errsize, "out of memory reading image '%s'", path);
		png_longjmp(png, 1);
	}
	for (png_uint_32 y = 0; y < h; y++)
		sp->rows[y] = sp->data + rowbytes * y;
	png_read_image(png, sp->rows);
	png_read_end(png, NULL);

	int och = paletted ? (has_trns ? 4 : 3) : ch;
	sp->px = malloc(sizeof(float) * n * (size_t)och);
	if (!sp->px || (paletted && !(sp->index = malloc(n)))) {
		snprintf(err, errsize, "out of memory reading image '%s'", path);
		png_longjmp(png, 1);
	}
	for (png_uint_32 y = 0; y < h; y++) {
		const unsigned char *r = sp->rows[y];
		for (png_uint_32 x = 0; x < w; x++) {
			size_t i = (size_t)y * w + x;
			float *d = &sp->px[i * (size_t)och];
			if (paletted) {
				int k = r[x];
				sp->index[i] = (unsigned char)k;
				png_color c = k < nplte ? plte[k] : (png_color){0, 0, 0};
				d[0] = c.red / 255.0f;
				d[1] = c.green / 255.0f;
				d[2] = c.blue / 255.0f;
				if (och == 4)
					d[3] = (k < ntrns ? trns_alpha[k] : 255) * (1.0f / 255.0f);
			} else if (bits == 16) {
				for (int c = 0; c < ch; c++) {
					const unsigned char *s = &r[((size_t)x * (size_t)ch + (size_t)c) * 2];
					d[c] = (float)(s[0] << 8 | s[1]) * (1.0f / 65535.0f);
				}
			} else {
				for (int c = 0; c < ch; c++)
					d[c] = r[(size_t)x * (size_t)ch + (size_t)c] * (1.0f / 255.0f);
			}
		}
	}
	double g = 0;
	int intent;
	if (png_get_gAMA(png, info, &g) && g > 0 && !png_get_sRGB(png, info, &intent))
		out->file_gamma = (float)(round(100 / g) / 100);
	out->width = (int)w;
	out->height = (int)h;
	out->channels = och;
	out->px = sp->px;
	out->index = sp->index;
	out->palette_size = paletted ? nplte : 0;
	out->bits = bits == 16 ? 16 : 8;
	out->is_float = 0;
	snprintf(out->format, sizeof out->format, "png");
	sp->px = NULL;
	sp->index = NULL;
	png_destroy_read_struct(&png, &info, NULL);
	read_state_free(sp);
	return 0;
}

/* tgappm.c: the TGA and PPM writers (see formats.h). Both formats are a
 * fixed header and the samples; TGA's run-length packets are the only
 * encoding work. */
#include "image/formats.h"

#include <stdlib.h>
#include <string.h>

static void put_le16(unsigned char *p, int v)
{
	p[0] = (unsigned char)(v & 0xff);
	p[1] = (unsigned char)((v >> 8) & 0xff);
}

/* One TGA pixel: blue, green, red[, alpha]. */
static void tga_pixel(unsigned char *d, const uint8_t *s, int channels)
{
	d[0] = s[2];
	d[1] = s[1];
	d[2] = s[0];
	if (channels == 4)
		d[3] = s[3];
}

/* Run-length packets for one row of n pixels into out (at most
 * n * (1 + channels) bytes); returns the bytes used. A packet holds 1 to
 * 128 pixels: a run of one repeated pixel (header 0x80 | count - 1), or
 * literal pixels (header count - 1); packets never cross rows. */
static size_t tga_rle_row(unsigned char *out, const uint8_t *row, int n, int channels)
{
	size_t o = 0;
	int i = 0;
	size_t px = (size_t)channels;
	while (i < n) {
		int run = 1;
		while (i + run < n && run < 128 && !memcmp(row + (size_t)(i + run) * px, row + (size_t)i * px, px))
			run++;
		if (run > 1) {
			out[o++] = (unsigned char)(0x80 | (run - 1));
			tga_pixel(out + o, row + (size_t)i * px, channels);
			o += px;
			i += run;
			continue;
		}
		/* Literals up to the next pair of equal pixels. */
		int lit = 1;
		while (i + lit < n && lit < 128 &&
		       !(i + lit + 1 < n && !memcmp(row + (size_t)(i + lit) * px, row + (size_t)(i + lit + 1) * px, px)))
			lit++;
		out[o++] = (unsigned char)(lit - 1);
		for (int k = 0; k < lit; k++, o += px)
			tga_pixel(out + o, row + (size_t)(i + k) * px, channels);
		i += lit;
	}
	return o;
}

int img_tga_write(FILE *fp, const struct img_samples *s, bool rle, char *err, size_t errsize)
{
	if (s->bits != 8 || s->width > 65535 || s->height > 65535) {
		snprintf(err, errsize, "TGA holds 8-bit images of at most 65535x65535 pixels");
		return 1;
	}
	unsigned char h[18] = {0};
	h[2] = rle ? 10 : 2;
	put_le16(h + 12, s->width);
	put_le16(h + 14, s->height);
	h[16] = (unsigned char)(8 * s->channels);
	/* Rows from the top (bit 5), and the alpha bits per pixel. */
	h[17] = (unsigned char)(0x20 | (s->channels == 4 ? 8 : 0));
	size_t px = (size_t)s->channels, n = (size_t)s->width;
	unsigned char *buf = malloc(n * (px + 1) + 1);
	if (!buf) {
		snprintf(err, errsize, "out of memory writing a TGA");
		return 1;
	}
	bool ok = fwrite(h, 1, sizeof h, fp) == sizeof h;
	for (int y = 0; ok && y < s->height; y++) {
		const uint8_t *row = s->u8 + (size_t)y * n * px;
		size_t len;
		if (rle) {
			len = tga_rle_row(buf, row, s->width, s->channels);
		} else {
			for (size_t x = 0; x < n; x++)
				tga_pixel(buf + x * px, row + x * px, s->channels);
			len = n * px;
		}
		ok = fwrite(buf, 1, len, fp) == len;
	}
	free(buf);
	if (!ok)
		snprintf(err, errsize, "write failed");
	return ok ? 0 : 1;
}

int img_ppm_write(FILE *fp, const struct img_samples *s, char *err, size_t errsize)
{
	size_t n = (size_t)s->width, bytes = (size_t)(s->bits / 8);
	unsigned char *buf = malloc(n * 3 * bytes + 1);
	if (!buf) {
		snprintf(err, errsize, "out of memory writing a PPM");
		return 1;
	}
	bool ok = fprintf(fp, "P6\n%d %d\n%d\n", s->width, s->height, s->bits == 16 ? 65535 : 255) > 0;
	size_t ch = (size_t)s->channels;
	for (int y = 0; ok && y < s->height; y++) {
		for (size_t x = 0; x < n; x++)
			for (size_t c = 0; c < 3; c++) {
				size_t k = ((size_t)y * n + x) * ch + c;
				if (bytes == 1) {
					buf[x * 3 + c] = s->u8[k];
				} else {
					/* 16-bit samples are big-endian. */
					buf[(x * 3 + c) * 2] = (unsigned char)(s->u16[k] >> 8);
					buf[(x * 3 + c) * 2 + 1] = (unsigned char)s->u16[k];
				}
			}
		ok = fwrite(buf, 1, n * 3 * bytes, fp) == n * 3 * bytes;
	}
	free(buf);
	if (!ok)
		snprintf(err, errsize, "write failed");
	return ok ? 0 : 1;
}

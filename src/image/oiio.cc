// oiio.cc: the lucent-oiio.so module: writes and reads images through OpenImageIO
// behind the C entry points named in oiio.h. Nothing C++ leaks out: every
// exception and error becomes a return code.
#include "image/oiio.h"

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

using namespace OIIO;

static void set_err(char *err, unsigned n, const std::string &msg)
{
	if (err && n) {
		std::snprintf(err, n, "%s", msg.c_str());
	}
}

extern "C" oiio_write_fn lucent_oiio_write;

extern "C" int lucent_oiio_write(const char *path, const char *format, int width, int height, int channels,
                          enum oiio_type type, const void *pixels, int srgb, char *err, unsigned errsize)
{
	try {
		auto out = ImageOutput::create(format);
		if (!out) {
			set_err(err, errsize, std::string("no image writer for format '") + format + "'");
			return 1;
		}
		TypeDesc td = type == OIIO_UINT8 ? TypeDesc::UINT8 : type == OIIO_UINT16 ? TypeDesc::UINT16 : TypeDesc::FLOAT;
		ImageSpec spec(width, height, channels, td);
		if (channels == 4) {
			spec.alpha_channel = 3;
			/* Integer pixels come unassociated (output.c): no conversion. */
			if (type != OIIO_FLOAT)
				spec.attribute("oiio:UnassociatedAlpha", 1);
		}
		spec.attribute("Software", "lucent");
		if (srgb)
			spec.attribute("oiio:ColorSpace", "sRGB");
		else
			spec.attribute("oiio:ColorSpace", "Linear");
		if (!out->open(path, spec)) {
			set_err(err, errsize, out->geterror());
			return 1;
		}
		if (!out->write_image(td, pixels)) {
			set_err(err, errsize, out->geterror());
			out->close();
			return 1;
		}
		if (!out->close()) {
			set_err(err, errsize, out->geterror());
			return 1;
		}
		return 0;
	} catch (const std::exception &e) {
		set_err(err, errsize, e.what());
		return 1;
	} catch (...) {
		set_err(err, errsize, "unknown OpenImageIO failure");
		return 1;
	}
}

// ---- reading ----

// The palette of a paletted file, and a copy of the file whose palette
// entry i has the colour (i, 0, 0) and no transparency, so that the red
// channel of the copy, read through OpenImageIO, is the palette index.
struct palette_copy {
	std::vector<unsigned char> bytes;
	std::vector<unsigned char> rgb;  // the palette's colours, 3 per entry
	int size = 0;
};

static uint32_t crc32_png(const unsigned char *p, size_t n)
{
	uint32_t c = 0xffffffffu;
	for (size_t i = 0; i < n; i++) {
		c ^= p[i];
		for (int k = 0; k < 8; k++)
			c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1)));
	}
	return c ^ 0xffffffffu;
}

static uint32_t be32(const unsigned char *p) { return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3]; }
static void put_be32(unsigned char *p, uint32_t v) { p[0] = v >> 24; p[1] = v >> 16; p[2] = v >> 8; p[3] = v; }

// PNG: colour type 3 has a PLTE chunk; tRNS gives entries alpha.
static bool png_palette(const std::vector<unsigned char> &f, palette_copy &pc)
{
	static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
	if (f.size() < 8 + 25 || std::memcmp(f.data(), sig, 8) != 0)
		return false;
	bool paletted = false;
	std::vector<unsigned char> out(f.begin(), f.begin() + 8);
	for (size_t at = 8; at + 12 <= f.size();) {
		uint32_t len = be32(&f[at]);
		if (len > f.size() - at - 12)
			return false;
		const unsigned char *type = &f[at + 4];
		size_t whole = 12 + (size_t)len;
		if (!std::memcmp(type, "IHDR", 4) && len >= 13) {
			paletted = f[at + 8 + 9] == 3;
		} else if (!std::memcmp(type, "PLTE", 4) && paletted) {
			pc.size = (int)(len / 3);
			pc.rgb.assign(f.begin() + at + 8, f.begin() + at + 8 + 3 * (len / 3));
			std::vector<unsigned char> c(f.begin() + at, f.begin() + at + whole);
			for (uint32_t i = 0; i < len / 3; i++) {
				c[8 + 3 * i] = (unsigned char)i;
				c[8 + 3 * i + 1] = c[8 + 3 * i + 2] = 0;
			}
			put_be32(&c[8 + len], crc32_png(&c[4], 4 + len));
			out.insert(out.end(), c.begin(), c.end());
			at += whole;
			continue;
		} else if (!std::memcmp(type, "tRNS", 4) && paletted) {
			at += whole;
			continue;
		}
		out.insert(out.end(), f.begin() + at, f.begin() + at + whole);
		at += whole;
	}
	if (!paletted || pc.size == 0)
		return false;
	pc.bytes.swap(out);
	return true;
}

// GIF: a global colour table and/or the first image's local one; a
// graphic control extension may name a transparent index.
static bool gif_palette(const std::vector<unsigned char> &f, palette_copy &pc)
{
	if (f.size() < 13 || (std::memcmp(f.data(), "GIF87a", 6) && std::memcmp(f.data(), "GIF89a", 6)))
		return false;
	std::vector<unsigned char> c(f);
	auto patch_table = [&](size_t at, int n) {
		if (at + 3 * (size_t)n > c.size())
			return false;
		pc.rgb.assign(c.begin() + at, c.begin() + at + 3 * n);
		for (int i = 0; i < n; i++) {
			c[at + 3 * i] = (unsigned char)i;
			c[at + 3 * i + 1] = c[at + 3 * i + 2] = 0;
		}
		pc.size = n;
		return true;
	};
	size_t at = 13;
	if (f[10] & 0x80) {
		int n = 2 << (f[10] & 7);
		if (!patch_table(at, n))
			return false;
		at += 3 * (size_t)n;
	}
	while (at < c.size()) {
		if (c[at] == 0x21 && at + 2 < c.size()) {          // extension
			if (c[at + 1] == 0xf9 && at + 3 < c.size())
				c[at + 3] &= (unsigned char)~1u;            // no transparent index
			at += 2;
			while (at < c.size() && c[at] != 0)
				at += 1 + (size_t)c[at];
			at++;
		} else if (c[at] == 0x2c && at + 10 <= c.size()) { // the first image
			if (c[at + 9] & 0x80) {
				int n = 2 << (c[at + 9] & 7);
				if (!patch_table(at + 10, n))
					return false;
			}
			break;
		} else {
			break;
		}
	}
	if (pc.size == 0)
		return false;
	pc.bytes.swap(c);
	return true;
}

// TGA: image types 1 and 9 are colour-mapped; entries of 24 or 32 bits
// (BGR[A]) can carry the index in red.
static bool tga_palette(const std::vector<unsigned char> &f, palette_copy &pc)
{
	if (f.size() < 18 || f[1] != 1 || (f[2] != 1 && f[2] != 9))
		return false;
	int first = f[3] | f[4] << 8, len = f[5] | f[6] << 8, bits = f[7];
	if (bits != 24 && bits != 32)
		return false;
	size_t at = 18 + (size_t)f[0], step = (size_t)bits / 8;
	if (at + step * (size_t)len > f.size() || first + len > 256)
		return false;
	std::vector<unsigned char> c(f);
	pc.rgb.assign(3 * (size_t)(first + len), 0);
	for (int i = 0; i < len; i++) {
		unsigned char *e = &c[at + step * (size_t)i];
		pc.rgb[3 * (first + i)] = e[2];
		pc.rgb[3 * (first + i) + 1] = e[1];
		pc.rgb[3 * (first + i) + 2] = e[0];
		e[0] = e[1] = 0;
		e[2] = (unsigned char)(first + i);
		if (step == 4)
			e[3] = 255;
	}
	pc.size = first + len;
	pc.bytes.swap(c);
	return true;
}

static bool read_file(const char *path, std::vector<unsigned char> &bytes)
{
	FILE *fp = std::fopen(path, "rb");
	if (!fp)
		return false;
	unsigned char buf[65536];
	size_t n;
	while ((n = std::fread(buf, 1, sizeof buf, fp)) > 0)
		bytes.insert(bytes.end(), buf, buf + n);
	bool ok = !std::ferror(fp);
	std::fclose(fp);
	return ok;
}

// Read the palette indices of a paletted file through a patched copy in a
// temporary file. Returns a malloc'd width*height array, or NULL.
static unsigned char *read_indices(const palette_copy &pc, const char *ext, int width, int height)
{
	const char *dir = std::getenv("TMPDIR");
	std::string tmpl = std::string(dir && *dir ? dir : "/tmp") + "/lucent-paletteXXXXXX" + ext;
	std::vector<char> name(tmpl.begin(), tmpl.end());
	name.push_back(0);
	int fd = mkstemps(name.data(), (int)std::strlen(ext));
	if (fd < 0)
		return nullptr;
	bool ok = write(fd, pc.bytes.data(), pc.bytes.size()) == (ssize_t)pc.bytes.size();
	close(fd);
	unsigned char *idx = nullptr;
	if (ok) {
		ImageSpec config;
		config.attribute("oiio:UnassociatedAlpha", 1);
		auto in = ImageInput::open(name.data(), &config);
		if (in && in->spec().width == width && in->spec().height == height) {
			idx = (unsigned char *)std::malloc((size_t)width * height);
			if (idx && !in->read_image(0, 0, 0, 1, TypeDesc::UINT8, idx)) {
				std::free(idx);
				idx = nullptr;
			}
		}
		if (in)
			in->close();
	}
	unlink(name.data());
	return idx;
}

extern "C" oiio_read_fn lucent_oiio_read;

extern "C" int lucent_oiio_read(const char *path, struct oiio_image *out, char *err, unsigned errsize)
{
	*out = oiio_image{};
	try {
		ImageSpec config;
		// Samples as stored: OpenImageIO would otherwise premultiply
		// straight-alpha files (PNG, TGA) as it reads them.
		config.attribute("oiio:UnassociatedAlpha", 1);
		auto in = ImageInput::open(path, &config);
		if (!in) {
			std::string e = OIIO::geterror();
			set_err(err, errsize, e.empty() ? std::string("cannot read image '") + path + "'" : e);
			return 1;
		}
		const ImageSpec &spec = in->spec();
		int w = spec.width, h = spec.height, nch = spec.nchannels, alpha = spec.alpha_channel;
		if (w <= 0 || h <= 0 || nch <= 0 || (size_t)w * h > ((size_t)1 << 31) / 16) {
			set_err(err, errsize, std::string("image '") + path + "' has an unusable size");
			return 1;
		}
		// OpenImageIO 2.4's GIF reader says channel 4 of 4: then the
		// channel named A.
		if (alpha >= nch)
			alpha = -1;
		for (int c = 0; alpha < 0 && c < nch && c < (int)spec.channelnames.size(); c++)
			if (spec.channelnames[c] == "A" || spec.channelnames[c] == "Alpha")
				alpha = c;
		std::vector<float> all((size_t)w * h * nch);
		if (!in->read_image(0, 0, 0, nch, TypeDesc::FLOAT, all.data())) {
			set_err(err, errsize, in->geterror());
			return 1;
		}
		// Colour channels: the first three that are not alpha (one for grey).
		int colour[3], ncolour = 0;
		for (int c = 0; c < nch && ncolour < 3; c++)
			if (c != alpha)
				colour[ncolour++] = c;
		if (ncolour == 2)
			ncolour = 1;
		int och = ncolour + (alpha >= 0 ? 1 : 0);
		float *px = (float *)std::malloc(sizeof(float) * (size_t)w * h * och);
		if (!px) {
			set_err(err, errsize, "out of memory reading an image");
			return 1;
		}
		for (size_t i = 0; i < (size_t)w * h; i++) {
			const float *s = &all[i * nch];
			float *d = &px[i * och];
			for (int c = 0; c < ncolour; c++)
				d[c] = s[colour[c]];
			if (alpha >= 0)
				d[ncolour] = s[alpha];
		}
		out->width = w;
		out->height = h;
		out->channels = och;
		out->px = px;
		out->bits = (int)spec.format.size() * 8;
		out->is_float = spec.format.is_floating_point();
		out->file_gamma = spec.get_float_attribute("oiio:Gamma", 0.0f);
		std::snprintf(out->format, sizeof out->format, "%s", in->format_name());
		in->close();

		std::vector<unsigned char> bytes;
		palette_copy pc;
		std::string fmt = out->format;
		const char *ext = fmt == "png" ? ".png" : fmt == "gif" ? ".gif" : fmt == "targa" ? ".tga" : nullptr;
		if (ext && read_file(path, bytes) &&
		    (fmt == "png" ? png_palette(bytes, pc) : fmt == "gif" ? gif_palette(bytes, pc) : tga_palette(bytes, pc))) {
			out->index = read_indices(pc, ext, w, h);
			if (out->index) {
				out->palette_size = pc.size;
				// The colours from the palette itself: OpenImageIO may
				// blacken transparent GIF pixels, POV-Ray keeps them.
				if (ncolour == 3)
					for (size_t i = 0; i < (size_t)w * h; i++) {
						size_t e = 3 * (size_t)out->index[i];
						for (int c = 0; c < 3 && e + 2 < pc.rgb.size(); c++)
							px[i * och + c] = pc.rgb[e + c] / 255.0f;
					}
			}
		}
		return 0;
	} catch (const std::exception &e) {
		std::free(out->px);
		std::free(out->index);
		*out = oiio_image{};
		set_err(err, errsize, e.what());
		return 1;
	} catch (...) {
		std::free(out->px);
		std::free(out->index);
		*out = oiio_image{};
		set_err(err, errsize, "unknown OpenImageIO failure");
		return 1;
	}
}

// oiio.cc: the lucent-oiio.so module: writes images through OpenImageIO
// behind the C entry points named in oiio.h. Nothing C++ leaks out: every
// exception and error becomes a return code.
#include "image/oiio.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

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
		if (channels == 4)
			spec.alpha_channel = 3;
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

/* shade.c: the formulas of the material model (see shade.h). Each was
 * measured against POV-Ray 3.7 renders of a flat surface lit and seen at
 * known angles (tests/unit/test_shade.c records the figures). */
#include "render/shade.h"

#include <math.h>

double shade_metallic_curve(double c)
{
	/* x: the angle as a fraction of a right angle. The curve rises from
	 * about 0.0003 at normal incidence to 1 just before grazing. */
	double x = fabs(acos(fmin(1.0, fmax(-1.0, c)))) / (M_PI / 2);
	double d = x - 1.12;
	double f = 0.014567225 / (d * d) - 0.011612903;
	return fmin(1.0, fmax(0.0, f));
}

rgb shade_metallic(rgb pig, double m, double c)
{
	double k = m * (1 - shade_metallic_curve(c));
	return rgb_make(1 + k * (pig.r - 1), 1 + k * (pig.g - 1), 1 + k * (pig.b - 1));
}

double shade_fresnel(double c, double n)
{
	c = fabs(c);
	double g2 = n * n + c * c - 1;
	if (g2 <= 0)
		return 1;
	double g = sqrt(g2);
	double a = (g - c) / (g + c);
	double b = (c * (g + c) - 1) / (c * (g - c) + 1);
	return 0.5 * a * a * (1 + b * b);
}

double shade_albedo_diffuse(double b) { return (b + 1) / 2; }

double shade_albedo_phong(double n) { return (n + 1) / 2; }

double shade_albedo_specular(double n) { return (n + 2) / (4 * (2 - pow(2, -n / 2))); }

rgb shade_fade(const struct interior *in, double d)
{
	rgb fc = in->fade_color;
	if (in->fade_power >= 1000) {
		double k = -d / in->fade_distance;
		return rgb_make(exp(k * (1 - fc.r)), exp(k * (1 - fc.g)), exp(k * (1 - fc.b)));
	}
	double a = 1 / (1 + pow(d / in->fade_distance, in->fade_power));
	return rgb_make(fc.r + (1 - fc.r) * a, fc.g + (1 - fc.g) * a, fc.b + (1 - fc.b) * a);
}

bool shade_refract(vec3 d, vec3 n, double eta, vec3 *out)
{
	double ci = -v3_dot(n, d);
	double k = 1 - eta * eta * (1 - ci * ci);
	if (k < 0)
		return false;
	*out = v3_norm(v3_add(v3_scale(d, eta), v3_scale(n, eta * ci - sqrt(k))));
	return true;
}

double shade_caustics(double c, double power)
{
	/* Measured: the light doubles where the shadow ray crosses the surface
	 * head-on and the excess falls as cos^(45 power) with the angle. */
	return 1 + pow(fabs(c), 45 * power);
}

rgb shade_irid(double a, double th, double c, rgb wl)
{
	/* Measured: the phase is 4 pi th c / wavelength, c being the mean of
	 * the light's and the viewer's incidence cosines. */
	double k = 4 * M_PI * th * c;
	return rgb_make(a * cos(k / wl.r), a * cos(k / wl.g), a * cos(k / wl.b));
}

/* POV-Ray 3.7's spectrum for dispersion, measured: the colour of the
 * spectrum from its red end up to u = k / 70 (u running from 0, red, to
 * 1, violet), k = 0 to 70. The colour of a band is the difference of this
 * integral at its ends, linear between the steps (POV-Ray renders the
 * bands of 2 to 151 samples within 3e-5 of it: a white background seen
 * through a prism, one band at a time crossing an edge between black and
 * white, in 16-bit output). The whole spectrum is not quite white. */
enum { SPECTRUM_STEPS = 70 };
static const double spectrum_integral[SPECTRUM_STEPS + 1][3] = {
	{0.000000, 0.000000, 0.000000}, {0.009812, 0.000000, 0.000000}, {0.024003, 0.000000, 0.000000},
	{0.042207, 0.000000, 0.000000}, {0.064103, 0.000000, 0.000000}, {0.089510, 0.000000, 0.000000},
	{0.117998, 0.000000, 0.000000}, {0.149310, 0.000000, 0.000000}, {0.183108, 0.000000, 0.000000},
	{0.219104, 0.000000, 0.000000}, {0.257008, 0.000000, 0.000000}, {0.296498, 0.000000, 0.000000},
	{0.337408, 0.001907, 0.000000}, {0.379202, 0.008103, 0.000000}, {0.421607, 0.018296, 0.000000},
	{0.464500, 0.032303, 0.000000}, {0.507408, 0.049897, 0.000000}, {0.550103, 0.070695, 0.000000},
	{0.592310, 0.094606, 0.000000}, {0.633601, 0.121401, 0.000000}, {0.673701, 0.150607, 0.000000},
	{0.712398, 0.182193, 0.000000}, {0.749310, 0.215900, 0.000000}, {0.784207, 0.251301, 0.000000},
	{0.816602, 0.288304, 0.000000}, {0.846403, 0.326696, 0.000000}, {0.873198, 0.366003, 0.000000},
	{0.896803, 0.406302, 0.000000}, {0.916701, 0.446998, 0.000000}, {0.932708, 0.488106, 0.000000},
	{0.944503, 0.529305, 0.000000}, {0.951812, 0.570306, 0.000000}, {0.954299, 0.610895, 0.000000},
	{0.954299, 0.650797, 0.000306}, {0.954299, 0.689799, 0.004395}, {0.954299, 0.727596, 0.012208},
	{0.954299, 0.764004, 0.023301}, {0.954299, 0.798703, 0.037706}, {0.954299, 0.831601, 0.055101},
	{0.954299, 0.862196, 0.075197}, {0.954299, 0.890501, 0.097994}, {0.954299, 0.916106, 0.123202},
	{0.954299, 0.938796, 0.150607}, {0.954299, 0.958297, 0.179996}, {0.954299, 0.974395, 0.211201},
	{0.954299, 0.986893, 0.244008}, {0.954299, 0.995499, 0.278203}, {0.954299, 1.000000, 0.313604},
	{0.954299, 1.000000, 0.349997}, {0.954299, 1.000000, 0.387198}, {0.954299, 1.000000, 0.424995},
	{0.954299, 1.000000, 0.463203}, {0.954299, 1.000000, 0.501595}, {0.954299, 1.000000, 0.540002},
	{0.954299, 1.000000, 0.578104}, {0.954299, 1.000000, 0.615900}, {0.954299, 1.000000, 0.652995},
	{0.954299, 1.000000, 0.689403}, {0.954299, 1.000000, 0.724697}, {0.955306, 1.000000, 0.758801},
	{0.957305, 1.000000, 0.791501}, {0.960311, 1.000000, 0.822508}, {0.963913, 1.000000, 0.851805},
	{0.968002, 1.000000, 0.878996}, {0.972412, 1.000000, 0.904006}, {0.976898, 1.000000, 0.926605},
	{0.981201, 1.000000, 0.946594}, {0.985306, 1.000000, 0.963699}, {0.988907, 1.000000, 0.977799},
	{0.991806, 1.000000, 0.988694}, {0.993805, 1.000000, 0.996201},
};

/* The colour of the spectrum from red up to u (0 to 1). */
static rgb spectrum_to(double u)
{
	double x = u * SPECTRUM_STEPS;
	int k = (int)x;
	if (k >= SPECTRUM_STEPS)
		k = SPECTRUM_STEPS - 1;
	double f = x - k;
	const double *a = spectrum_integral[k], *b = spectrum_integral[k + 1];
	return rgb_make(a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]));
}

rgb shade_dispersion_color(int i, int n)
{
	rgb lo = spectrum_to((double)i / n), hi = spectrum_to((double)(i + 1) / n);
	return rgb_make(hi.r - lo.r, hi.g - lo.g, hi.b - lo.b);
}

double shade_dispersion_hue(int i, int n)
{
	return (i + 0.5) / n - 0.5;
}

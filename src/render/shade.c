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

/* The weights of red, green and blue at spectrum position h (0 red, 2
 * green, 4 violet): overlapping ramps. */
static rgb spectrum(double h)
{
	return rgb_make(fmax(0, 1 - h / 2), fmax(0, 1 - fabs(h - 2) / 2), fmin(1, fmax(0, (h - 2) / 2)));
}

rgb shade_dispersion_color(int i, int n)
{
	rgb sum = rgb_make(0, 0, 0);
	for (int j = 0; j < n; j++)
		sum = rgb_add(sum, spectrum(4.0 * j / (n - 1)));
	rgb c = spectrum(4.0 * i / (n - 1));
	/* A channel no sample covers (green with 2 samples) is shared evenly. */
	return rgb_make(sum.r > 0 ? c.r / sum.r : 1.0 / n, sum.g > 0 ? c.g / sum.g : 1.0 / n,
	                sum.b > 0 ? c.b / sum.b : 1.0 / n);
}

double shade_dispersion_ior(double ior, double dispersion, int i, int n)
{
	double t = n > 1 ? (double)i / (n - 1) : 0.5;
	return ior * pow(dispersion, t - 0.5);
}

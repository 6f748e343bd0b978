/* shade.h: the formulas of POV-Ray's material model, as pure functions of
 * their inputs, so that the tracer (trace.c) reads as the order in which
 * they are applied and the unit tests can check each against values POV-Ray
 * renders. Angles are passed as cosines; colours are linear rgb. */
#ifndef LUCENT_SHADE_H
#define LUCENT_SHADE_H

#include "math/vec.h"
#include "scene/color.h"
#include "scene/texture.h"

/* POV-Ray's empirical metallic curve: how far a metallic highlight or
 * reflection turns from the surface's colour toward the light's at an angle
 * whose cosine is c (0 at normal incidence, 1 at grazing). */
double shade_metallic_curve(double c);
/* The colour a metallic term multiplies light by: 1 + m (1 - curve) (pig - 1),
 * so m = 0 leaves the light white and m = 1 tints it with the pigment. */
rgb shade_metallic(rgb pig, double m, double c);

/* Unpolarised Fresnel reflectance at incidence cosine c (0..1) into a
 * medium of relative index n (n2 / n1); 1 under total internal reflection. */
double shade_fresnel(double c, double n);

/* The factors `albedo` multiplies a finish amount by, so that the amount is
 * the total reflectance rather than the peak: diffuse (brilliance b),
 * phong (phong_size n), specular (exponent n = 1 / roughness). */
double shade_albedo_diffuse(double b);
double shade_albedo_phong(double n);
double shade_albedo_specular(double n);

/* The share of light that passes d units through interior in (fade_distance,
 * fade_power, fade_color): 1 / (1 + (d / D)^P) blended toward fade_color, or
 * exp(-d (1 - fade_color) / D) when P >= 1000. Colour 1 without fading. */
rgb shade_fade(const struct interior *in, double d);

/* The refracted direction of unit d through a surface with unit normal n
 * facing the incoming ray (n.d < 0), relative index eta = n1 / n2. Returns
 * false under total internal reflection. */
bool shade_refract(vec3 d, vec3 n, double eta, vec3 *out);

/* POV-Ray's fake caustics: the factor a shadow ray's light is multiplied by
 * where it crosses a transparent surface at cosine c with caustics power. */
double shade_caustics(double c, double power);

/* Iridescence (thin-film interference): the colour added, per unit of light,
 * for irid amount a, film thickness th (after turbulence), at light
 * incidence cosine c, with the three wavelengths of irid_wavelength. */
rgb shade_irid(double a, double th, double c, rgb wavelength);

/* Dispersion splits a ray into n bands of the spectrum, i = 0 (red) to
 * n - 1 (violet), as POV-Ray 3.7 does (measured): band i's colour is the
 * spectrum's share between i / n and (i + 1) / n, the n colours adding up
 * to nearly white (0.9938, 1, 0.9962); its hue, the centre of the band, is
 * (i + 1/2) / n - 1/2, and an interior of ior I and dispersion D refracts
 * it with ior I * D^hue. */
rgb shade_dispersion_color(int i, int n);
double shade_dispersion_hue(int i, int n);

#endif

/* camera.c: camera description and projections (see camera.h).
 *
 * Every mapping below was measured from POV-Ray 3.7: direction maps (a
 * hollow sphere of radius 1000 around the camera whose pigment is
 * 0.5 + 0.5 * (one coordinate of the hit) / 1000, rendered to 16-bit
 * linear PNGs) and origin maps (the same on a plane) give each pixel's ray
 * to about 2e-5; the formulas reproduce them to that precision. Notation:
 * (x, y) the image position in pixels from the top-left corner, w x h the
 * image, u = x/w - 1/2 and v = 1/2 - y/h (each in [-1/2, 1/2], v up);
 * D, R, U the direction, right and up vectors, Dn, Rn, Un their unit
 * vectors. */
#include "scene/camera.h"

#include "scene/texture.h"

#include <math.h>
#include <stdlib.h>

/* POV-Ray's omnimax lens: the angle off the axis of a point at radius r of
 * the lens plane, in radians (an odd polynomial fitted to POV-Ray's
 * renders: residual under 2e-5 radians over the whole image circle). */
static double omnimax_theta(double r)
{
	double r2 = r * r;
	return r * (1.411269 + r2 * (-0.09439 + r2 * 0.25674));
}

/* The radius at which the omnimax lens sees 45 degrees off its axis.
 * Images wider than they are high keep the lower edge there. */
static double omnimax_r45(void)
{
	double r = 0.55;
	for (int i = 0; i < 8; i++) {
		double r2 = r * r;
		double f = omnimax_theta(r) - M_PI / 4;
		double df = 1.411269 + r2 * (3 * -0.09439 + r2 * 5 * 0.25674);
		r -= f / df;
	}
	return r;
}

struct camera camera_default(void)
{
	struct camera c = {
		.kind = CAMERA_PERSPECTIVE,
		.location = {0, 0, 0},
		.direction = {0, 0, 1},
		.right = {1.33, 0, 0},
		.up = {0, 1, 0},
		.sky = {0, 1, 0},
		.angle = -1,
		.v_angle = -1,
		.confidence = 0.9,
		.variance = 1.0 / 128,
	};
	camera_update(&c);
	return c;
}

void camera_copy(struct camera *dst, const struct camera *src)
{
	*dst = *src;
	if (dst->bokeh)
		pigment_ref(dst->bokeh);
	if (dst->mesh)
		dst->mesh->refs++;
	if (dst->normal)
		normal_ref(dst->normal);
}

void mesh_cam_unref(struct mesh_cam *m)
{
	if (!m || --m->refs > 0)
		return;
	free(m->first);
	free(m->face);
	free(m);
}

double camera_ray_limit(const struct camera *c)
{
	if (c->kind == CAMERA_MESH && c->mesh && c->mesh->max_dist > 0)
		return c->mesh->max_dist;
	return INFINITY;
}

void camera_clear(struct camera *c)
{
	pigment_unref(c->bokeh);
	c->bokeh = NULL;
	mesh_cam_unref(c->mesh);
	c->mesh = NULL;
	normal_unref(c->normal);
	c->normal = NULL;
}

void camera_update(struct camera *c)
{
	c->dn = v3_norm(c->direction);
	c->rn = v3_norm(c->right);
	c->un = v3_norm(c->up);
	c->rl = v3_len(c->right);
	c->ul = v3_len(c->up);
	double h = c->angle, v = c->v_angle;
	if (c->kind == CAMERA_SPHERICAL) {
		if (h < 0)
			h = 360;
		if (v < 0)
			v = h / 2;
	} else {
		if (h < 0)
			h = 90;
		v = h;
	}
	if (c->kind == CAMERA_PANORAMIC)
		h = v = 180;
	c->h_rad = h * (M_PI / 180);
	c->v_rad = v * (M_PI / 180);
	c->focal_dist = v3_dot(v3_sub(c->focal_point, c->location), c->dn);

	/* Omnimax: the lens plane is [-1,1]^2 scaled so that up/right keep
	 * their ratio q; a short image (q < 1) keeps the top edge at the
	 * zenith, and one shorter than the 45-degree point allows widens
	 * instead (measured: q = 0.5 and 0.75 both scale y by 0.77915). */
	double q = c->rl > 0 ? c->ul / c->rl : 1;
	double qmin = (1 + omnimax_r45()) / 2;
	double sy = q < qmin ? qmin : q;
	c->omni_sx = sy / q;
	c->omni_sy = sy;
	c->omni_oy = sy < 1 ? 1 - sy : 0;
}

bool camera_look_at(struct camera *c, vec3 at, bool *along_sky)
{
	double dl = v3_len(c->direction), rl = v3_len(c->right), ul = v3_len(c->up);
	/* A left-handed frame has right = up x direction pointing along right;
	 * a scene that flips right (right -x*4/3) keeps the flip. So does a
	 * frame whose handedness is 0 (up along direction, or right across
	 * both): measured, `right x up z` (direction z) looking straight down
	 * or at any other point sees the world mirrored, as with right -x. */
	double hand = v3_dot(v3_cross(c->up, c->direction), c->right);
	*along_sky = false;
	vec3 d = v3_sub(at, c->location);
	if (v3_len(d) == 0)
		return false;
	d = v3_norm(d);
	vec3 r = v3_cross(c->sky, d);
	if (v3_len(r) < 1e-10 * v3_len(c->sky) || v3_len(c->sky) == 0) {
		/* Straight along the sky: POV-Ray keeps the right vector given. */
		*along_sky = true;
		r = c->right;
		if (v3_len(v3_cross(r, d)) < 1e-10 * v3_len(r) || v3_len(r) == 0)
			return false;
	}
	r = v3_norm(r);
	vec3 u = v3_norm(v3_cross(d, r));
	if (!(hand > 0))
		r = v3_neg(r);
	c->direction = v3_scale(d, dl);
	c->right = v3_scale(r, rl);
	c->up = v3_scale(u, ul);
	camera_update(c);
	return true;
}

void camera_set_angle(struct camera *c, double degrees)
{
	double rl = v3_len(c->right);
	double half = degrees * (M_PI / 360.0);
	double dl = 0.5 * rl / tan(half);
	c->direction = v3_scale(v3_norm(c->direction), dl);
	camera_update(c);
}

void camera_transform(struct camera *c, const struct xform *t)
{
	c->location = mat_point(&t->fwd, c->location);
	c->direction = mat_dir(&t->fwd, c->direction);
	c->right = mat_dir(&t->fwd, c->right);
	c->up = mat_dir(&t->fwd, c->up);
	c->sky = mat_dir(&t->fwd, c->sky);
	c->focal_point = mat_point(&t->fwd, c->focal_point);
	camera_update(c);
}

/* a*A + b*B + d*D */
static vec3 comb(double a, vec3 A, double b, vec3 B, double d, vec3 D)
{
	return v3(a * A.x + b * B.x + d * D.x, a * A.y + b * B.y + d * D.y, a * A.z + b * B.z + d * D.z);
}

/* The pinhole ray of every projection; false outside its image. */
static bool pinhole(const struct camera *c, double u, double v, struct ray *r)
{
	r->org = c->location;
	switch (c->kind) {
	case CAMERA_MESH:
		return false; /* its rays come from camera_mesh_ray */
	case CAMERA_PERSPECTIVE:
		/* D + u R + v U */
		r->dir = v3_add(c->direction, comb(u, c->right, v, c->up, 0, c->dn));
		break;
	case CAMERA_ORTHOGRAPHIC:
		/* Parallel rays along D from location + u R + v U. */
		r->org = v3_add(c->location, comb(u, c->right, v, c->up, 0, c->dn));
		r->dir = c->dn;
		break;
	case CAMERA_FISHEYE: {
		/* Polar: (2u |R|, 2v |U|) at radius rad <= 1 sees rad * angle/2
		 * off the axis. */
		double x0 = 2 * u * c->rl, y0 = 2 * v * c->ul;
		double rad = sqrt(x0 * x0 + y0 * y0);
		if (rad > 1)
			return false;
		if (rad == 0) {
			r->dir = c->dn;
			break;
		}
		double th = rad * c->h_rad / 2, s = sin(th) / rad;
		r->dir = comb(s * x0, c->rn, s * y0, c->un, cos(th), c->dn);
		break;
	}
	case CAMERA_OMNIMAX: {
		double x1 = 2 * u * c->omni_sx, y1 = 2 * v * c->omni_sy + c->omni_oy;
		double rad = sqrt(x1 * x1 + y1 * y1);
		if (rad > 1)
			return false;
		if (rad == 0) {
			r->dir = c->dn;
			break;
		}
		double th = omnimax_theta(rad), s = sin(th) / rad;
		/* The film ends below at the plane 45 degrees below the axis:
		 * rays must lie on the side of it that holds direction + up. */
		if (s * y1 + cos(th) < 0)
			return false;
		r->dir = comb(s * x1, c->rn, s * y1, c->un, cos(th), c->dn);
		break;
	}
	case CAMERA_ULTRA_WIDE_ANGLE: {
		/* Horizontal angle u*angle, vertical v*angle*|U|/|R|. */
		double h = u * c->h_rad, vv = v * c->h_rad * (c->rl > 0 ? c->ul / c->rl : 1);
		r->dir = comb(sin(h), c->rn, sin(vv), c->un, cos(h) * cos(vv), c->dn);
		break;
	}
	case CAMERA_PANORAMIC: {
		/* Latitude and longitude over 180 degrees each, on the ellipsoid
		 * of the vectors as given (their lengths count). */
		double h = u * M_PI, vv = v * M_PI;
		r->dir = comb(cos(vv) * sin(h), c->right, sin(vv), c->up, cos(vv) * cos(h), c->direction);
		break;
	}
	case CAMERA_SPHERICAL: {
		double h = u * c->h_rad, vv = v * c->v_rad;
		r->dir = comb(cos(vv) * sin(h), c->rn, sin(vv), c->un, cos(vv) * cos(h), c->dn);
		break;
	}
	case CAMERA_CYLINDER:
		switch (c->cylinder_type) {
		case 1: { /* vertical axis, fixed viewpoint */
			double h = u * c->h_rad;
			r->dir = comb(sin(h), c->rn, v, c->up, cos(h), c->dn);
			break;
		}
		case 2: { /* horizontal axis, fixed viewpoint */
			double vv = v * c->h_rad;
			r->dir = comb(u, c->right, sin(vv), c->un, cos(vv), c->dn);
			break;
		}
		case 3: { /* vertical axis, the viewpoint moves along up */
			double h = u * c->h_rad;
			r->org = v3_madd(c->location, c->up, v);
			r->dir = comb(sin(h), c->rn, 0, c->un, cos(h), c->dn);
			break;
		}
		default: { /* 4: horizontal axis, the viewpoint moves along right */
			double vv = v * c->h_rad;
			r->org = v3_madd(c->location, c->right, u);
			r->dir = comb(0, c->rn, sin(vv), c->un, cos(vv), c->dn);
			break;
		}
		}
		break;
	}
	r->dir = v3_norm(r->dir);
	return true;
}

/* The lens ray from lens point (lu, lv) around org through focus: the
 * origin moved across the lens, in the plane of right and up. */
static void through_lens(const struct camera *c, vec3 org, vec3 focus, double lu, double lv, struct ray *r)
{
	double k = c->aperture / 2;
	r->org = v3_add(org, comb(lu * k, c->rn, lv * k, c->un, 0, c->dn));
	r->dir = v3_norm(v3_sub(focus, r->org));
}

/* Focal blur: move the origin across the lens and aim at the point where
 * the pinhole ray meets the plane in focus. POV-Ray's lens has radius
 * aperture/4 (measured: the blur of an edge at distance z with focus at f
 * spans aperture/4 * |1/f - 1/z| |D|/|R| of the image width, for f = 1, 2,
 * 3, 5 and z on both sides of f). A ray running along the focal plane
 * (its cosine with the direction under 1e-6) keeps its pinhole path. */
bool camera_ray(const struct camera *c, double x, double y, int w, int h, double lu, double lv,
                struct ray *r)
{
	if (c->kind == CAMERA_PERSPECTIVE && (lu != 0 || lv != 0)) {
		/* With the pinhole ray left unnormalised (one square root and
		 * division less a sample): it starts at the location, so it
		 * meets the plane in focus at focal_dist / (d . D) times d. */
		vec3 d = v3_add(c->direction, comb(x / w - 0.5, c->right, 0.5 - y / h, c->up, 0, c->dn));
		double dd = v3_dot(d, c->dn);
		r->org = c->location;
		if (dd <= 0 || dd * dd < 1e-12 * v3_dot(d, d))
			r->dir = v3_norm(d);
		else
			through_lens(c, c->location, v3_madd(c->location, d, c->focal_dist / dd), lu, lv, r);
		return true;
	}
	if (!pinhole(c, x / w - 0.5, 0.5 - y / h, r))
		return false;
	if (lu == 0 && lv == 0)
		return true;
	double cosd = v3_dot(r->dir, c->dn);
	if (cosd < 1e-6)
		return true;
	double t = (c->focal_dist - v3_dot(v3_sub(r->org, c->location), c->dn)) / cosd;
	through_lens(c, r->org, v3_madd(r->org, r->dir, t), lu, lv, r);
	return true;
}

/* Mesh camera. Where POV-Ray puts a pixel, measured with -A renders of
 * meshes whose faces are numbered by the colour they see: pixel (col, row)
 * is face w * max(row - 1, 0) + col in distributions 0 to 2 (the first two
 * rows share the first row of faces), and in distribution 3 the uv point
 * (X / w, 1 - Y / h) with X = col except w - 1.5 in the last column and
 * Y = row except 0.5 in the first row. */
static bool mesh_face_ray(const struct camera *c, const struct camera_face *f, vec3 org, vec3 n, struct ray *r)
{
	if (c->direction.z < -1e-10)
		n = v3_neg(n);
	/* location's z moves the origin along the face's normal. */
	r->org = v3_madd(org, n, c->location.z);
	r->dir = n;
	(void)f;
	return true;
}

/* The barycentric weights (of corners 1 and 2) of uv point (u, v) in the
 * face's uv triangle, which may turn either way (measured: a face whose uv
 * triangle turns clockwise shoots its ray as one turning anticlockwise
 * does); false outside it or where the triangle is flat. */
static bool uv_weights(const struct camera_face *f, double u, double v, double *b1, double *b2)
{
	double ax = f->uv[0][0], ay = f->uv[0][1];
	double e1x = f->uv[1][0] - ax, e1y = f->uv[1][1] - ay;
	double e2x = f->uv[2][0] - ax, e2y = f->uv[2][1] - ay;
	double det = e1x * e2y - e1y * e2x;
	if (det == 0 || !isfinite(det))
		return false;
	double px = u - ax, py = v - ay;
	*b1 = (px * e2y - py * e2x) / det;
	*b2 = (e1x * py - e1y * px) / det;
	return *b1 >= 0 && *b2 >= 0 && *b1 + *b2 <= 1;
}

bool camera_mesh_ray(const struct camera *c, double x, double y, int w, int h, int k, struct ray *r)
{
	const struct mesh_cam *m = c->mesh;
	int col = (int)floor(x), row = (int)floor(y);
	if (m->dist == 3) {
		double X = col >= w - 1 ? w - 1.5 : x - 0.5, Y = row <= 0 ? 0.5 : y - 0.5;
		double u = X / w, v = 1 - Y / h;
		for (size_t i = 0; i < m->first[1]; i++) {
			const struct camera_face *f = &m->face[i];
			double b1, b2;
			if (!f->has_uv || !uv_weights(f, u, v, &b1, &b2))
				continue;
			double b0 = 1 - b1 - b2;
			vec3 org = v3_madd(v3_madd(v3_scale(f->p[0], b0), f->p[1], b1), f->p[2], b2);
			vec3 n = f->n;
			if (m->smooth && f->has_normals) {
				vec3 s = v3_madd(v3_madd(v3_scale(f->vn[0], b0), f->vn[1], b1), f->vn[2], b2);
				if (v3_dot(s, s) > 0)
					n = v3_norm(s);
			}
			return mesh_face_ray(c, f, org, n, r);
		}
		return false;
	}
	if (row > 0)
		row--;
	size_t face, lo = 0, hi = m->first[m->nmesh];
	switch (m->dist) {
	case 0:
		/* Ray k of a pixel: mesh k's face at the pixel number. */
		lo = m->first[k];
		hi = m->first[k + 1];
		face = lo + (size_t)w * (size_t)row + (size_t)col;
		break;
	case 1:
		/* The meshes' faces in one list. The manual puts ray k at w h k
		 * faces further, but POV-Ray 3.7 shoots only the first (measured:
		 * 2 rays over two meshes of 12 faces on a 4 x 3 image give the
		 * colour of the first ray's face alone). */
		if (k > 0)
			return false;
		face = (size_t)w * (size_t)row + (size_t)col;
		break;
	default: {
		/* Side by side: mesh j sees the j-th of nmesh equal blocks of
		 * width bw. Its face is bw * row + col with the image's column,
		 * not the block's (measured: two meshes of 6 faces on a 4 x 3
		 * image show faces 2, 3 of the second mesh at the top right). */
		int bw = w / m->nmesh;
		int j = bw > 0 ? col / bw : 0;
		if (j >= m->nmesh)
			return false;
		lo = m->first[j];
		hi = m->first[j + 1];
		face = lo + (size_t)bw * (size_t)row + (size_t)col;
		break;
	}
	}
	if (face < lo || face >= hi)
		return false;
	return mesh_face_ray(c, &m->face[face], m->face[face].centroid, m->face[face].n, r);
}

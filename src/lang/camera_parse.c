/* camera_parse.c: the camera statement, with POV-Ray 3.7's rules of
 * order: the projection type comes first; the other items may come in any
 * order, because they take effect in a fixed one when the block closes:
 * the vectors as given, then angle (the perspective and orthographic
 * direction's length), then an orthographic camera's size, then look_at,
 * then the transformations in order. A declared camera may only be moved
 * (transformations). */
#include "lang/parser.h"

#include "geom/mesh.h"
#include "scene/camera.h"

#include <limits.h>
#include <stdlib.h>

/* What a camera block said, beside the vectors stored at once. */
struct cam_items {
	bool angle_given;     /* `angle` (an orthographic one may have no value) */
	bool right_given, up_given;
	bool look;            /* look_at given */
	vec3 look_at;
	struct srcpos look_pos;
	bool moved;
	struct xform xf;      /* the transformations, composed in order */
};

/* Append mesh o's faces, in world space, to m. */
static void add_mesh_faces(struct mesh_cam *m, const struct object *o, size_t *cap)
{
	size_t n = mesh_face_total(o), have = m->first[m->nmesh];
	if (have + n > *cap) {
		*cap = (have + n) * 2;
		m->face = realloc(m->face, *cap * sizeof *m->face);
		if (!m->face)
			abort();
	}
	for (size_t i = 0; i < n; i++) {
		struct mesh_face mf;
		mesh_face(o, i, &mf);
		struct camera_face *f = &m->face[have + i];
		for (int k = 0; k < 3; k++) {
			f->p[k] = mat_point(&o->xf.fwd, mf.corner[k]);
			f->vn[k] = mf.has_normals ? v3_norm(mat_normal(&o->xf.inv, mf.normal[k])) : v3(0, 0, 0);
			f->uv[k][0] = mf.uv[k][0];
			f->uv[k][1] = mf.uv[k][1];
		}
		f->has_normals = mf.has_normals;
		f->has_uv = mf.has_uv;
		f->centroid = v3_scale(v3_add(f->p[0], v3_add(f->p[1], f->p[2])), 1.0 / 3);
		f->n = v3_norm(v3_cross(v3_sub(f->p[2], f->p[0]), v3_sub(f->p[1], f->p[0])));
	}
}

/* mesh_camera := mesh_camera '{' RAYS DISTRIBUTION [MAX_DISTANCE] { mesh_item } [smooth] '}'
 * mesh_item := a mesh or mesh2 object statement (mesh { IDENT ... } too:
 *              POV-Ray takes them whole, modifiers included)
 * (no commas between the numbers: POV-Ray refuses them.) */
static void parse_mesh_camera(struct parser *p, struct camera *c)
{
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	struct mesh_cam *m = calloc(1, sizeof *m);
	if (!m)
		abort();
	m->refs = 1;
	mesh_cam_unref(c->mesh);
	c->mesh = m; /* owned by the camera from here, freed with it on an error */
	c->kind = CAMERA_MESH;
	struct srcpos rpos = parse_peek(p)->pos;
	double rays = parse_float(p);
	if (rays < 1)
		parse_error_at(p, rpos, "a mesh camera needs at least 1 ray per pixel, not %g", rays);
	/* Held as an int: more rays per pixel than that mean nothing, since
	 * distribution 0 needs a mesh per ray, 2 and 3 take one ray and 1
	 * shoots only the first (see camera_mesh_ray). */
	m->rays = rays < INT_MAX ? (int)rays : INT_MAX;
	struct srcpos dpos = parse_peek(p)->pos;
	double dist = parse_float(p);
	if (!(dist >= 0 && dist < 4))
		parse_error_at(p, dpos, "a mesh camera's distribution type must be 0, 1, 2 or 3, not %g", dist);
	m->dist = (int)dist;
	/* A max_distance of 0 or below sets no limit (measured: -1 and 0
	 * see as far as no number). */
	if (parse_starts_expression(p)) {
		double md = parse_float(p);
		m->max_dist = md > 0 ? md : 0;
	}
	size_t cap = 0;
	m->first = malloc(sizeof *m->first);
	if (!m->first)
		abort();
	m->first[0] = 0;
	for (;;) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_KEYWORD || (t->kw != KW_MESH && t->kw != KW_MESH2))
			break;
		struct srcpos mpos = t->pos;
		struct object *o = parse_object(p, false);
		if (!mesh_is(o)) {
			object_free(o);
			parse_error_at(p, mpos, "a mesh camera's mesh must be a mesh or mesh2 object");
		}
		size_t *first = realloc(m->first, (size_t)(m->nmesh + 2) * sizeof *first);
		if (!first)
			abort();
		m->first = first;
		add_mesh_faces(m, o, &cap);
		m->first[m->nmesh + 1] = m->first[m->nmesh] + mesh_face_total(o);
		m->nmesh++;
		object_free(o);
	}
	const struct token *t = parse_peek(p);
	if (t->kind == TOK_KEYWORD && t->kw == KW_SMOOTH) {
		/* POV-Ray refuses it with the other distributions too. */
		if (m->dist != 3)
			parse_error(p, "smooth applies to a mesh camera of distribution 3 only, not %d", m->dist);
		parse_advance(p);
		m->smooth = true;
	}
	if (m->nmesh == 0)
		parse_expected(p, "a mesh or mesh2 object (a mesh camera needs at least one)");
	if (m->dist == 0 && m->nmesh < m->rays)
		parse_error_at(p, rpos, "distribution 0 needs a mesh per ray: %d rays per pixel but %d mesh%s", m->rays,
		               m->nmesh, m->nmesh == 1 ? "" : "es");
	if ((m->dist == 2 || m->dist == 3) && m->rays != 1)
		parse_error_at(p, rpos, "distribution %d takes 1 ray per pixel, not %d", m->dist, m->rays);
	parse_expect(p, TOK_RBRACE);
}

/* camera_type := perspective | orthographic | fisheye | ultra_wide_angle
 *              | omnimax | panoramic | spherical | cylinder FLOAT | mesh_camera
 * Returns false if the current token is none. */
static bool parse_camera_type(struct parser *p, struct camera *c)
{
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_KEYWORD)
		return false;
	switch (t->kw) {
	case KW_PERSPECTIVE: c->kind = CAMERA_PERSPECTIVE; break;
	case KW_ORTHOGRAPHIC: c->kind = CAMERA_ORTHOGRAPHIC; break;
	case KW_FISHEYE: c->kind = CAMERA_FISHEYE; break;
	case KW_ULTRA_WIDE_ANGLE: c->kind = CAMERA_ULTRA_WIDE_ANGLE; break;
	case KW_OMNIMAX: c->kind = CAMERA_OMNIMAX; break;
	case KW_PANORAMIC: c->kind = CAMERA_PANORAMIC; break;
	case KW_SPHERICAL: c->kind = CAMERA_SPHERICAL; break;
	case KW_MESH_CAMERA:
		parse_mesh_camera(p, c);
		return true;
	case KW_CYLINDER: {
		parse_advance(p);
		struct srcpos at = parse_peek(p)->pos;
		double n = parse_float(p);
		/* POV-Ray truncates: cylinder 2.7 is type 2. */
		if (!(n >= 1 && n < 5))
			parse_error_at(p, at, "a cylinder camera's type must be 1, 2, 3 or 4, not %g", n);
		c->kind = CAMERA_CYLINDER;
		c->cylinder_type = (int)n;
		return true;
	}
	default: return false;
	}
	parse_advance(p);
	return true;
}

static const char *kind_name(enum camera_kind k)
{
	switch (k) {
	case CAMERA_PERSPECTIVE: return "perspective";
	case CAMERA_ORTHOGRAPHIC: return "orthographic";
	case CAMERA_FISHEYE: return "fisheye";
	case CAMERA_ULTRA_WIDE_ANGLE: return "ultra_wide_angle";
	case CAMERA_OMNIMAX: return "omnimax";
	case CAMERA_PANORAMIC: return "panoramic";
	case CAMERA_CYLINDER: return "cylinder";
	case CAMERA_SPHERICAL: return "spherical";
	case CAMERA_MESH: return "mesh_camera";
	}
	return "camera";
}

/* Is the current token one of the projection keywords? */
static bool at_camera_type(struct parser *p)
{
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_KEYWORD)
		return false;
	switch (t->kw) {
	case KW_PERSPECTIVE: case KW_ORTHOGRAPHIC: case KW_FISHEYE: case KW_ULTRA_WIDE_ANGLE:
	case KW_OMNIMAX: case KW_PANORAMIC: case KW_SPHERICAL: case KW_CYLINDER: case KW_MESH_CAMERA:
		return true;
	default:
		return false;
	}
}

/* The optional second number of `angle` and `blur_samples`: where an
 * expression starts, after an optional comma (POV-Ray also takes a comma
 * with nothing after it). */
static bool second_number(struct parser *p)
{
	parse_accept(p, TOK_COMMA);
	return parse_starts_expression(p);
}

/* angle_item := angle FLOAT [[','] FLOAT]   (the second: spherical only)
 *             | angle                       (orthographic: keep the size) */
static void parse_angle(struct parser *p, struct camera *c, struct cam_items *it)
{
	parse_advance(p);
	it->angle_given = true;
	if (c->kind == CAMERA_ORTHOGRAPHIC && !parse_starts_expression(p))
		return;
	struct srcpos at = parse_peek(p)->pos;
	double a = parse_float(p);
	if (a < 0)
		parse_error_at(p, at, "a camera's angle cannot be negative (%g)", a);
	if ((c->kind == CAMERA_PERSPECTIVE || c->kind == CAMERA_ORTHOGRAPHIC) && a >= 180)
		parse_error_at(p, at, "a%s %s camera's angle must be less than 180 degrees, not %g",
		               c->kind == CAMERA_ORTHOGRAPHIC ? "n" : "", kind_name(c->kind), a);
	c->angle = a;
	if (c->kind == CAMERA_SPHERICAL && second_number(p)) {
		at = parse_peek(p)->pos;
		double v = parse_float(p);
		if (v < 0)
			parse_error_at(p, at, "a camera's angle cannot be negative (%g)", v);
		c->v_angle = v;
	}
}

/* A count of blur_samples: POV-Ray's int of the number (a fraction is cut
 * off; past an int's range it is the smallest int), at least 1. */
static int blur_count(struct parser *p, struct srcpos at, double x)
{
	int n = parse_int_of(x);
	if (n < 1) {
		if (x >= 1)
			parse_error_at(p, at, "blur_samples must be at most 2147483647, not %g", x);
		parse_error_at(p, at, "blur_samples must be at least 1, not %g", x);
	}
	return n;
}

/* blur_samples := blur_samples [MIN [',']] MAX
 * One number is the maximum; the minimum is then 4, or 7 from a maximum of
 * 7 up (never above the maximum). */
static void parse_blur_samples(struct parser *p, struct camera *c)
{
	parse_advance(p);
	struct srcpos at = parse_peek(p)->pos;
	int a = blur_count(p, at, parse_float(p));
	if (second_number(p)) {
		struct srcpos bt = parse_peek(p)->pos;
		int b = blur_count(p, bt, parse_float(p));
		if (a > b)
			parse_error_at(p, at, "the minimum of blur_samples (%d) is larger than the maximum (%d)", a, b);
		c->blur_samples_min = a;
		c->blur_samples_max = b;
	} else {
		int min = a < 7 ? 4 : 7;
		c->blur_samples_max = a;
		c->blur_samples_min = min < a ? min : a;
	}
}

/* bokeh := bokeh '{' { pigment } '}'
 * An empty bokeh leaves the lens round, as in POV-Ray; a second pigment
 * modifies the first, as on an object. */
static void parse_bokeh(struct parser *p, struct camera *c)
{
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	while (!parse_accept(p, TOK_RBRACE)) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_KEYWORD || t->kw != KW_PIGMENT)
			parse_expected(p, "pigment or '}' in bokeh");
		parse_pigment(p, &c->bokeh);
	}
}

/* Apply what the block said in POV-Ray's order (see the file comment). */
static void finish_camera(struct parser *p, struct camera *c, struct cam_items *it)
{
	if (c->kind == CAMERA_PERSPECTIVE && it->angle_given && c->angle > 0)
		camera_set_angle(c, c->angle);
	if (c->kind == CAMERA_ORTHOGRAPHIC && (it->angle_given || (!it->right_given && !it->up_given))) {
		/* The view of a perspective camera with the same direction (and
		 * angle) at the look_at point: right and up grow by the distance
		 * to it over the direction's length. Without look_at the point
		 * is POV-Ray's default look_at, <0,0,1>. */
		if (it->angle_given && c->angle > 0)
			camera_set_angle(c, c->angle);
		vec3 at = it->look ? it->look_at : v3(0, 0, 1);
		double dl = v3_len(c->direction);
		if (dl > 0) {
			double k = v3_len(v3_sub(at, c->location)) / dl;
			c->right = v3_scale(c->right, k);
			c->up = v3_scale(c->up, k);
		}
	}
	camera_update(c);
	if (it->look) {
		bool along_sky;
		if (v3_len(v3_sub(it->look_at, c->location)) == 0)
			parse_error_at(p, it->look_pos, "look_at cannot be the camera's own location");
		if (!camera_look_at(c, it->look_at, &along_sky))
			parse_error_at(p, it->look_pos, "look_at points along both the sky and the right vector");
		if (along_sky)
			parse_warning_at(p, it->look_pos,
			                 "look_at points along the sky vector: the right vector given is kept instead");
	}
	if (it->moved)
		camera_transform(c, &it->xf);
}

/* camera := camera '{' ( IDENT { transformation }
 *                      | { camera_type } { camera_item } ) '}'
 * camera_item := location V | look_at V | right V | up V | direction V
 *              | sky V | angle_item | aperture F | focal_point V
 *              | blur_samples | confidence F | variance F | bokeh
 *              | normal | transformation
 * c holds the camera to start from (camera_default()). */
void parse_camera(struct parser *p, struct camera *c)
{
	c->pos = parse_peek(p)->pos;
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	struct cam_items it = {.xf = xform_identity()};

	const struct value *v = parse_ident_value(p);
	if (v) {
		if (v->kind != VAL_CAMERA)
			parse_wrong_kind(p, v, "a camera");
		struct srcpos pos = c->pos;
		camera_clear(c);
		camera_copy(c, v->cam);
		c->pos = pos;
		parse_advance(p);
		while (!parse_accept(p, TOK_RBRACE)) {
			struct xform step;
			if (parse_transform_item(p, &step)) {
				camera_transform(c, &step);
				continue;
			}
			parse_expected(p, "a transformation or '}' (a declared camera may only be moved)");
		}
		return;
	}

	while (parse_camera_type(p, c))
		;
	while (!parse_accept(p, TOK_RBRACE)) {
		const struct token *t = parse_peek(p);
		struct srcpos at = t->pos;
		struct xform step;
		if (parse_transform_item(p, &step)) {
			it.xf = xform_compose(&step, &it.xf);
			it.moved = true;
			continue;
		}
		if (at_camera_type(p))
			parse_error(p, "the camera type (%s) must come first in the camera block", kw_names[t->kw]);
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "a camera item or '}'");
		switch (t->kw) {
		case KW_LOCATION: parse_advance(p); c->location = parse_vector(p); break;
		case KW_RIGHT: parse_advance(p); c->right = parse_vector(p); it.right_given = true; break;
		case KW_UP: parse_advance(p); c->up = parse_vector(p); it.up_given = true; break;
		case KW_DIRECTION: parse_advance(p); c->direction = parse_vector(p); break;
		case KW_SKY: parse_advance(p); c->sky = parse_vector(p); break;
		case KW_ANGLE: parse_angle(p, c, &it); break;
		case KW_LOOK_AT:
			parse_advance(p);
			it.look = true;
			it.look_pos = at;
			it.look_at = parse_vector(p);
			break;
		case KW_APERTURE: parse_advance(p); c->aperture = parse_float(p); break;
		case KW_FOCAL_POINT: parse_advance(p); c->focal_point = parse_vector(p); break;
		case KW_BLUR_SAMPLES: parse_blur_samples(p, c); break;
		case KW_CONFIDENCE: {
			parse_advance(p);
			struct srcpos cpos = parse_peek(p)->pos;
			double conf = parse_float(p);
			if (!(conf > 0 && conf < 1)) {
				parse_warning_at(p, cpos, "confidence must be between 0 and 1, not %g: using 0.9", conf);
				conf = 0.9;
			}
			c->confidence = conf;
			break;
		}
		case KW_VARIANCE: parse_advance(p); c->variance = parse_float(p); break;
		case KW_BOKEH: parse_bokeh(p, c); break;
		case KW_NORMAL: parse_normal(p, &c->normal); break;
		default:
			parse_expected(p, "a camera item or '}'");
		}
	}
	finish_camera(p, c, &it);
}

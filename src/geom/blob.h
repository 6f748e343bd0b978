/* blob.h: the builder API of blob { ... }, POV-Ray's iso-surface of a sum
 * of component fields (src/geom/blob.c). A component of strength s and
 * radius r adds s (1 - d^2 / r^2)^2 where d < r, d being the distance to
 * a sphere's centre or to a cylinder's axis segment (hemispherical ends);
 * the surface is where the sum equals the threshold, the inside where it
 * is greater. doc/objects.md describes the object and how closely it
 * follows POV-Ray. */
#ifndef LUCENT_BLOB_H
#define LUCENT_BLOB_H

#include "scene/object.h"

/* A new blob with no components, threshold 1, sturm off (caller owns it;
 * free with object_free). It needs at least one component before use. */
struct object *blob_new(struct srcpos pos);
/* Add a component; returns its index. A cylinder's ends must differ
 * (blob_add_cylinder returns -1 and adds nothing otherwise: POV-Ray's
 * "degenerate cylindrical component"). */
int blob_add_sphere(struct object *o, vec3 center, double radius, double strength);
int blob_add_cylinder(struct object *o, vec3 end1, vec3 end2, double radius, double strength);
/* Move component i by t. `rigid`: t is a translate, a rotate or a uniform
 * scale, which a sphere without a transform of its own takes into its
 * centre and radius (POV-Ray does, and its bounds show it); anything else
 * (and every transform of a cylinder) is kept as the component's own. The
 * component's texture moves with it. */
void blob_transform_component(struct object *o, int i, const struct xform *t, bool rigid);
/* The texture holder of component i, for the parser to fill (NULL: the
 * blob's own texture there). */
struct texture **blob_component_texture(struct object *o, int i);
size_t blob_component_count(const struct object *o);
void blob_set_threshold(struct object *o, double threshold);
void blob_set_sturm(struct object *o, bool sturm);
/* hierarchy on|off: only a speed setting (the hits are the same). */
void blob_set_hierarchy(struct object *o, bool on);
/* The field of the blob at the object-space point p (the sum of the
 * components'), for tests and the inside test. */
double blob_density(const struct object *o, vec3 p);

#endif

/* mesh.h: triangle meshes, the object behind both mesh { } and mesh2 { }.
 *
 * The parser fills a builder (vertices, normals, uv vectors, a texture
 * list, faces that index them, an optional inside_vector) and hands it to
 * mesh_new, which drops degenerate faces, builds a bounding volume
 * hierarchy over the triangles in object space and returns the object. The
 * mesh data (arrays and hierarchy) are reference-counted and shared by
 * every copy of the object, so `object { M translate ... }` repeated a
 * thousand times costs a thousand small headers.
 *
 * A hit sets h->part to the triangle's index in the mesh's own (hierarchy)
 * order and h->u, h->v to the barycentric weights of its second and third
 * vertex. Triangles are tested with the watertight test of tri.h. */
#ifndef LUCENT_MESH_H
#define LUCENT_MESH_H

#include "scene/object.h"

#include <stddef.h>
#include <stdint.h>

/* "No index": a face without normals, uv vectors or textures. */
#define MESH_NONE UINT32_MAX

enum mesh_kind {
	MESH_KIND_MESH,  /* mesh { }: corners given by value, merged by the builder */
	MESH_KIND_MESH2, /* mesh2 { }: lists given in full, faces index them */
};

struct mesh_builder;

/* A new, empty builder. For MESH_KIND_MESH, vertices, normals, uv vectors
 * and textures that are added twice get the index of the first copy (so a
 * mesh { } of separate triangles shares its corners). For MESH_KIND_MESH2,
 * every add makes a new entry whose index is its position in its list. */
struct mesh_builder *mesh_builder_new(enum mesh_kind kind);
/* Free a builder that was not given to mesh_new (after a parse error). */
void mesh_builder_free(struct mesh_builder *b);

/* Append to the lists; each returns the entry's index. Normals are stored
 * normalised (POV-Ray's behaviour); a uv vector is <u, v>. The builder
 * takes its own reference to t. */
uint32_t mesh_add_vertex(struct mesh_builder *b, vec3 p);
uint32_t mesh_add_normal(struct mesh_builder *b, vec3 n);
uint32_t mesh_add_uv(struct mesh_builder *b, double u, double v);
uint32_t mesh_add_texture(struct mesh_builder *b, struct texture *t);

uint32_t mesh_vertex_count(const struct mesh_builder *b);
uint32_t mesh_normal_count(const struct mesh_builder *b);
uint32_t mesh_uv_count(const struct mesh_builder *b);
uint32_t mesh_texture_count(const struct mesh_builder *b);
uint32_t mesh_face_count(const struct mesh_builder *b);

/* Append a face with vertex indices v[0..2] and ntex (0, 1 or 3) texture
 * indices tex[0..ntex) (tex may be NULL when ntex is 0). Returns false, adding nothing, if an index is out of range of
 * the lists built so far; the new face is number mesh_face_count() - 1. */
bool mesh_add_face(struct mesh_builder *b, const uint32_t v[3], int ntex, const uint32_t *tex);
/* Give face `face` vertex normals (a smooth triangle) or uv vectors, by
 * index into the normal or uv list. False if an index is out of range.
 * For MESH_KIND_MESH2, when no face is given normals (normal_indices
 * omitted) and there are as many normals as vertices, mesh_new uses the
 * vertex indices instead; likewise for uv vectors. */
bool mesh_set_face_normals(struct mesh_builder *b, uint32_t face, const uint32_t n[3]);
bool mesh_set_face_uvs(struct mesh_builder *b, uint32_t face, const uint32_t uv[3]);
/* inside_vector: without one (or with a zero one) the mesh has no inside. */
void mesh_set_inside_vector(struct mesh_builder *b, vec3 dir);

/* The mesh object. Consumes b (also when it has no faces: such a mesh is
 * never hit). Degenerate faces (zero area) are dropped, as POV-Ray does. */
struct object *mesh_new(struct mesh_builder *b, struct srcpos pos);

/* The textures of the face hit by h: 1 (the face's texture), 3 (one per
 * vertex, for POV-Ray's vertex-texture interpolation, with the barycentric
 * weights in w) or 0 (the object's own). No references are added. */
int mesh_textures_at(const struct object *o, const struct hit *h, struct texture *tex[3], double w[3]);

/* What the tests and statistics want to know about a mesh object. */
struct mesh_stats {
	size_t triangles;   /* after dropping degenerate faces */
	size_t vertices;
	size_t nodes;       /* hierarchy nodes */
	size_t bytes;       /* memory of the shared data (arrays and hierarchy) */
	int refs;           /* objects sharing the data */
	const void *data;   /* identity of the shared data */
};
void mesh_get_stats(const struct object *o, struct mesh_stats *st);
/* The corners of triangle i (in the mesh's order, as in h->part). */
void mesh_triangle(const struct object *o, size_t i, vec3 corner[3]);

/* A face as declared (object space): for the mesh camera. */
struct mesh_face {
	vec3 corner[3];
	vec3 normal[3];       /* unit vertex normals when has_normals */
	double uv[3][2];      /* when has_uv */
	bool has_normals, has_uv;
};
/* Is o a mesh object (mesh or mesh2)? */
bool mesh_is(const struct object *o);
/* The number of faces kept (degenerate ones dropped, as POV-Ray does). */
size_t mesh_face_total(const struct object *o);
/* Face i (0 <= i < mesh_face_total) in declaration order. */
void mesh_face(const struct object *o, size_t i, struct mesh_face *f);

#endif

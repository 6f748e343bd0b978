// mesh.pov: rays through the shared edges and vertices of meshes
// (run.sh: mesh-silhouette). The meshes come from meshes.inc (made by
// meshes.py), drawn in one colour on a pure blue background:
//   - three copies of a closed icosphere (1280 faces, vertices on the unit
//     sphere), centred in the planes x = 0 or y = 0, which are mirror
//     planes of the mesh: the rays of the middle row (plane y = 0) and of
//     the middle column (plane x = 0) of this 161x121 image meet the mesh
//     exactly on the edges that lie in those planes, and the centre ray
//     goes exactly through the vertex at the pole of the middle copy;
//   - a flat grid of 24 x 24 squares split along diagonals, 1/8 unit per
//     pixel away, placed so that each ray that hits it passes through a
//     vertex (a quarter of them), the middle of an edge or the middle of
//     a diagonal: no ray hits a triangle's interior.
// The camera is at the origin with direction z*200, right x*161, up
// y*121: pixel (i, j) looks along (i - 80, 60 - j, 200), exactly for the
// middle row and column (whose offsets are 0.5 - 60.5/121 = 0 and
// 0.5 - 80.5/161 = 0), up to rounding elsewhere: then on which side of an
// edge the ray passes is decided by the last bits of the camera's
// arithmetic, which is the hard case for a mesh.
//
// Property (check.py inside): every pixel whose ray passes within the
// inradius of an icosphere (0.995472 times its radius, less 1e-3) or
// inside the grid's square (1e-3 from its border) shows the mesh, and
// every pixel whose ray misses all the circumscribed spheres and the
// square (by 1e-3) shows the background: zero holes, no stray hit.
//
// lucent passes: no hole among the 5971 pixels that must be covered.
// POV-Ray 3.7 FAILS: 309 holes, all in the grid, where rays through
// shared vertices and edges slip between the triangles (its icospheres
// have none).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "meshes.inc"

camera {
  location <0, 0, 0>
  direction z*200
  right x*image_width
  up y*image_height
}
light_source { <-20, 30, -20> color rgb 1 }
background { color rgb <0, 0, 1> }

#declare Tex = texture { pigment { color rgb <1, 0.6, 0.2> } finish { ambient 0.35 diffuse 0.65 } }
object { Icosphere scale 3 translate <0, 0, 25> texture { Tex } }
object { Icosphere scale 2.5 translate <6.5, 0, 25> texture { Tex } }
object { Icosphere scale 1.8 translate <0, -5.5, 25> texture { Tex } }
object { Grid texture { Tex } }

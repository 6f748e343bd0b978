#!/usr/bin/python3
"""tests/stability/meshes.py: writes meshes.inc, the two meshes of
mesh.pov, as mesh2 objects:

Icosphere: the closed mesh, an icosahedron subdivided 3 times (642
vertices, 1280 faces), every vertex on the unit sphere.

The icosahedron is the usual one, with vertices (0, +-1, +-phi),
(+-1, +-phi, 0), (+-phi, 0, +-1) before normalisation, so that the three
coordinate planes are mirror planes of the mesh: their vertices have a
coordinate exactly 0, mirrored vertices are exact negatives of each other
(IEEE arithmetic is symmetric under negation), and many edges lie exactly
in the planes x = 0 and y = 0. The poles (0, 0, +-1) are vertices from
level 1 on. Coordinates are printed with 17 significant digits, which
read back to the same doubles.

The include's header gives the inradius (distance from the centre to the
nearest face plane), the radius within which check.py's `inside` command
requires every ray to hit.

Grid: a square of 24 x 24 cells 1/4 wide, each split along a diagonal,
from (-9.5, -3, 25) to (-3.5, 3, 25). In mesh.pov's camera a pixel is
1/8 unit wide in the plane z = 25 and the pixel centres' rays meet that
plane at multiples of 1/8 (up to the rounding of the camera's
arithmetic): every ray that hits the grid passes through a vertex, the
middle of an edge or the middle of a diagonal. All the coordinates are
exact binary fractions.

Usage: meshes.py > meshes.inc
"""
import math
import sys


def icosphere(level):
    """Return (vertices, faces) of the icosphere subdivided `level` times."""
    phi = (1 + math.sqrt(5)) / 2
    verts = [(-1, phi, 0), (1, phi, 0), (-1, -phi, 0), (1, -phi, 0),
             (0, -1, phi), (0, 1, phi), (0, -1, -phi), (0, 1, -phi),
             (phi, 0, -1), (phi, 0, 1), (-phi, 0, -1), (-phi, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11),
             (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
             (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9),
             (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]

    def unit(v):
        n = math.sqrt(sum(c * c for c in v))
        return tuple(c / n for c in v)

    verts = [unit(v) for v in verts]
    for _ in range(level):
        middle = {}

        def mid(i, j):
            key = (min(i, j), max(i, j))
            if key not in middle:
                a, b = verts[i], verts[j]
                verts.append(unit(tuple((p + q) / 2 for p, q in zip(a, b))))
                middle[key] = len(verts) - 1
            return middle[key]

        split = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            split += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = split
    return verts, faces


def inradius(verts, faces):
    """Distance from the origin to the nearest face plane."""
    best = math.inf
    for f in faces:
        a, b, c = (verts[i] for i in f)
        u = [b[k] - a[k] for k in range(3)]
        w = [c[k] - a[k] for k in range(3)]
        n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
             u[0] * w[1] - u[1] * w[0])
        d = abs(sum(n[k] * a[k] for k in range(3))) / math.sqrt(sum(c * c for c in n))
        best = min(best, d)
    return best


def grid(n, x0, y0, step, z):
    """Return (vertices, faces) of an n x n grid of squares split along a
    diagonal, in the plane z, from (x0, y0)."""
    verts = [(x0 + i * step, y0 + j * step, z) for j in range(n + 1) for i in range(n + 1)]
    faces = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            faces += [(a, a + 1, a + n + 2), (a, a + n + 2, a + n + 1)]
    return verts, faces


def write_mesh(out, name, verts, faces):
    out.write('#declare %s = mesh2 {\n  vertex_vectors { %d,\n' % (name, len(verts)))
    out.write(',\n'.join('    <%.17g, %.17g, %.17g>' % v for v in verts))
    out.write('\n  }\n  face_indices { %d,\n' % len(faces))
    out.write(',\n'.join('    <%d, %d, %d>' % f for f in faces))
    out.write('\n  }\n}\n')


def main():
    out = sys.stdout
    verts, faces = icosphere(3)
    out.write('// meshes.inc: made by meshes.py; do not edit.\n')
    out.write('// Icosphere: an icosahedron subdivided 3 times, %d vertices, %d faces,\n'
              % (len(verts), len(faces)))
    out.write('// vertices on the unit sphere, inradius %.6f; the coordinate planes are\n'
              % inradius(verts, faces))
    out.write('// mirror planes.\n')
    write_mesh(out, 'Icosphere', verts, faces)
    out.write('// Grid: 24 x 24 squares 1/4 wide split along a diagonal, in the plane\n')
    out.write('// z = 25, from (-9.5, -3) to (-3.5, 3).\n')
    write_mesh(out, 'Grid', *grid(24, -9.5, -3, 0.25, 25))


if __name__ == '__main__':
    main()

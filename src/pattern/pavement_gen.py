#!/usr/bin/env python3
"""pavement_gen.py: the layouts of POV-Ray 3.7's `pavement` patterns, and the
generator of src/pattern/pavement_table.c from them.

    python3 src/pattern/pavement_gen.py --measure > src/pattern/pavement_layouts.txt
    python3 src/pattern/pavement_gen.py > src/pattern/pavement_table.c

A pavement paves the x-z plane with copies of one polyform: unit squares
(number_of_sides 4), unit triangles (3) or hexagons of side 1 (6) joined
into tiles of number_of_tiles cells. Which cells make a tile is a periodic
layout that POV-Ray chooses for each polyform; it was measured, not read:
--measure has POV-Ray 3.7.0 print function { pigment { pavement ... } } just
inside the middle of every edge of every cell over a window of some 25 x 25
cells. The value there is near 1 where the edge is a border between tiles
and well below 1 where it joins two cells of one tile, so the cells fall
into tiles; the smallest lattice of translations that keeps every cell's
neighbourhood is the layout's period.

What a cell needs to know is which of its neighbours are in its own tile:
its *mask*. pavement_layouts.txt holds, for each pavement, the period as
two lattice vectors in Hermite form (p, 0) and (q, r) in cell coordinates
and the masks of the p x r cells of one period (two per lattice cell for
triangles, up then down):

  squares   cell (i, j) = (floor x, floor z); bit k of the mask is the
            neighbour at (1,0) (1,1) (0,1) (-1,1) (-1,0) (-1,-1) (0,-1) (1,-1)
  triangles lattice point P(i, j) = (i + j/2, j sqrt(3)/2); up triangle
            P(i,j) P(i+1,j) P(i,j+1), down P(i+1,j) P(i+1,j+1) P(i,j+1);
            bits 5v .. 5v+4: the five other triangles around the cell's
            vertex v, counter-clockwise from the cell
  hexagons  centres (1 + 1.5 m, (m + 2 n) sqrt(3)/2), a corner at the
            origin; bit k: the neighbour across the edge whose outward
            normal is at 30 + 60 k degrees

How the value follows from the mask (the corners and the form, exterior
and interior settings) is in pavement.c; it too was measured.
"""
import math
import os
import subprocess
import sys
import tempfile

H = math.sqrt(3) / 2
COUNTS = {3: (1, 1, 1, 3, 4, 12), 4: (1, 1, 2, 5, 12, 35), 6: (1, 1, 3, 7, 22)}
HERE = os.path.dirname(os.path.abspath(__file__))
LAYOUTS = os.path.join(HERE, "pavement_layouts.txt")

# ---- cells ----


def tri_p(i, j):
    return (i + 0.5 * j, j * H)


def tri_cell_of(x, z):
    t = z / H
    s = x - 0.5 * t
    i, j = math.floor(s), math.floor(t)
    return (i, j, 0 if (s - i) + (t - j) < 1 else 1)


def tri_verts(c):
    """The vertices of triangle c and the direction (in 60 degree steps) in
    which the cell starts, counter-clockwise, around each."""
    i, j, d = c
    if d == 0:
        return [(tri_p(i, j), 0), (tri_p(i + 1, j), 2), (tri_p(i, j + 1), 4)]
    return [(tri_p(i + 1, j), 1), (tri_p(i + 1, j + 1), 3), (tri_p(i, j + 1), 5)]


def tri_sectors(v):
    r = 1 / math.sqrt(3)
    return [tri_cell_of(v[0] + r * math.cos(math.radians(30 + 60 * k)), v[1] + r * math.sin(math.radians(30 + 60 * k)))
            for k in range(6)]


def hex_centre(m, n):
    return (1 + 1.5 * m, H * m + 2 * H * n)


HEX_NB = ((1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1))


def cells(sides, R):
    """key -> polygon, over a window of about 2R x 2R cells."""
    C = {}
    if sides == 4:
        for j in range(-R, R):
            for i in range(-R, R):
                C[(i, j)] = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
    elif sides == 3:
        for j in range(-R, R):
            for i in range(-R - j // 2 - 1, R - j // 2 + 1):
                C[(i, j, 0)] = [tri_p(i, j), tri_p(i + 1, j), tri_p(i, j + 1)]
                C[(i, j, 1)] = [tri_p(i + 1, j), tri_p(i + 1, j + 1), tri_p(i, j + 1)]
    else:
        for m in range(-R, R):
            for n in range(-R - m // 2 - 1, R - m // 2 + 1):
                cx, cz = hex_centre(m, n)
                C[(m, n)] = [(cx + math.cos(math.pi / 3 * k), cz + math.sin(math.pi / 3 * k)) for k in range(6)]
    return C


def neighbours(sides, c):
    """The cells whose tile membership makes c's mask, in bit order."""
    if sides == 4:
        i, j = c
        return [(i + a, j + b) for a, b in ((1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1))]
    if sides == 6:
        m, n = c
        return [(m + a, n + b) for a, b in HEX_NB]
    out = []
    for v, k0 in tri_verts(c):
        s = tri_sectors(v)
        assert s[k0] == c
        out += [s[(k0 + k) % 6] for k in range(1, 6)]
    return out

# ---- measuring ----


def sample(body, pts):
    """POV-Ray's value of pigment { BODY } (grey map) at the points (x, z)."""
    with tempfile.TemporaryDirectory() as d:
        fi, fo, pov = (os.path.join(d, n) for n in ("in.txt", "out.txt", "t.pov"))
        with open(fi, "w") as f:
            f.write("".join("%.9f, %.9f,\n" % p for p in pts))
        with open(pov, "w") as f:
            f.write('#version 3.7;\nglobal_settings { assumed_gamma 1 }\n'
                    '#declare G = function { pigment { %s color_map { [0 rgb 0] [1 rgb 1] } } }\n'
                    '#fopen I "%s" read\n#fopen O "%s" write\n#while (defined(I))\n#read (I, X, Z)\n'
                    '#write (O, str(G(X, 0, Z).red, 0, 10), "\\n")\n#end\n#fclose O\n' % (body, fi, fo))
        subprocess.run(["povray", "-D", "-F", "+W1", "+H1", "+I" + pov], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return [float(l) for l in open(fo)][:len(pts)]


def measure_labels(sides, tiles, pattern, R=14):
    """Tile labels of the cells of a window, from the values next to the
    middle of each cell's edges."""
    C = cells(sides, R)
    body = "pavement number_of_sides %d number_of_tiles %d pattern %d" % (sides, tiles, pattern)
    key = lambda p: (round(p[0] * 1000), round(p[1] * 1000))
    pts, edges = [], []
    for k, poly in C.items():
        cx = sum(p[0] for p in poly) / len(poly)
        cz = sum(p[1] for p in poly) / len(poly)
        for a in range(len(poly)):
            p, q = poly[a], poly[(a + 1) % len(poly)]
            mx, mz = (p[0] + q[0]) / 2, (p[1] + q[1]) / 2
            l = math.hypot(cx - mx, cz - mz)
            pts.append((mx + 0.01 * (cx - mx) / l, mz + 0.01 * (cz - mz) / l))
            edges.append((k, frozenset((key(p), key(q)))))
    border = {}
    owners = {}
    for e, v in zip(edges, sample(body, pts)):
        border[e] = v > 0.9
        owners.setdefault(e[1], []).append(e[0])
    for ed, ks in owners.items():
        if len(ks) == 2 and border[(ks[0], ed)] != border[(ks[1], ed)]:
            raise SystemExit("%s: the two sides of an edge disagree" % body)
    lab, n = {}, 0
    for c in C:
        if c in lab:
            continue
        lab[c] = n
        stack = [c]
        while stack:
            k = stack.pop()
            poly = C[k]
            for a in range(len(poly)):
                ed = frozenset((key(poly[a]), key(poly[(a + 1) % len(poly)])))
                if border[(k, ed)]:
                    continue
                for o in owners[ed]:
                    if o != k and o not in lab:
                        lab[o] = n
                        stack.append(o)
        n += 1
    return lab


def lattice(sides, c):
    return (c[0], c[1])


def layout(sides, tiles, pattern):
    """(p, q, r, masks) for one pavement."""
    lab = measure_labels(sides, tiles, pattern)
    M = {}
    for c, L in lab.items():
        nb = neighbours(sides, c)
        if all(x in lab for x in nb):
            M[c] = sum(1 << k for k, x in enumerate(nb) if lab[x] == L)
    shift = lambda c, di, dj: (c[0] + di, c[1] + dj) + tuple(c[2:])
    for area in range(1, 400):
        for r in (r for r in range(1, area + 1) if area % r == 0):
            p = area // r
            for q in range(p):
                if all(M.get(shift(c, p, 0), m) == m and M.get(shift(c, q, r), m) == m for c, m in M.items()):
                    masks = []
                    for j in range(r):
                        for i in range(p):
                            for d in ((0, 1) if sides == 3 else (None,)):
                                masks.append(find(M, p, q, r, i, j, d))
                    return p, q, r, masks
    raise SystemExit("no period found")


def find(M, p, q, r, i, j, d):
    for k in range(-12, 13):
        for l in range(-12, 13):
            c = (i + k * p + l * q, j + l * r) + (() if d is None else (d,))
            if c in M:
                return M[c]
    raise SystemExit("cell (%d, %d) not measured" % (i, j))


def measure():
    print("# pavement layouts measured from POV-Ray 3.7.0 by pavement_gen.py --measure")
    print("# sides tiles pattern p q r masks...")
    for sides in (3, 4, 6):
        for tiles, n in enumerate(COUNTS[sides], 1):
            for pattern in range(1, n + 1):
                p, q, r, masks = layout(sides, tiles, pattern)
                print(sides, tiles, pattern, p, q, r, " ".join(str(m) for m in masks))
                sys.stdout.flush()

# ---- the C table ----


def emit():
    rows = [list(map(int, l.split())) for l in open(LAYOUTS) if l.strip() and not l.startswith("#")]
    w = sys.stdout.write
    w("/* pavement_table.c: the layouts of POV-Ray's `pavement` patterns (see\n"
      " * pavement_table.h). GENERATED by pavement_gen.py from the measured\n"
      " * pavement_layouts.txt: edit those, not this. */\n#include \"pattern/pavement_table.h\"\n\n")
    names = []
    for row in rows:
        s, t, n, p, q, r = row[:6]
        masks = row[6:]
        name = "m%d_%d_%d" % (s, t, n)
        names.append((s, t, n, p, q, r, name))
        w("static const unsigned short %s[] = {" % name)
        w(", ".join(str(m) for m in masks))
        w("};\n")
    w("\nconst struct pavement_layout pavement_layouts[PAVEMENT_COUNT] = {\n")
    for s, t, n, p, q, r, name in names:
        w("\t{%d, %d, %d, %d, %d, %d, %s},\n" % (s, t, n, p, q, r, name))
    w("};\n")
    if len(names) != sum(sum(c) for c in COUNTS.values()):
        raise SystemExit("pavement_layouts.txt is incomplete")


if __name__ == "__main__":
    if len(sys.argv) == 2 and sys.argv[1] == "--measure":
        measure()
    else:
        emit()

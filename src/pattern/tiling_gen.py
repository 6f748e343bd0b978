#!/usr/bin/env python3
"""tiling_gen.py: the geometry of POV-Ray 3.7's `tiling N` patterns, and the
generator of src/pattern/tiling_table.c from it.

    python3 src/pattern/tiling_gen.py > src/pattern/tiling_table.c
    python3 src/pattern/tiling_gen.py --check DIR   # compare with dumps

Every tiling is a periodic set of convex polygons in the x-z plane: two
lattice vectors and the polygons of one cell, each with its tile type.
The value at a point of a tile of type t (of N) is

    (t + 1 - min(1, d))/N,   d = min over the tile's edges of dist/rho

where dist is the distance from the point to the edge's line and rho the
edge's bevel width: the smallest inradius among the tiling's polygons,
except on the edges where POV-Ray bevels wider (tiling 22's dodecagon).

All of it was measured, not read: POV-Ray 3.7.0 was made to print
function { pigment { tiling N color_map { [0 rgb 0] [1 rgb 1] } } } on a
grid of 200 x 200 points over [-4, 4]^2 (a dump file DIR/tN.txt holds
lines "x z value"), the tile centres and ridges were read off the minima,
the polygons fitted, and --check confirms that every point agrees to
within 1e-5 (points on a boundary between two tiles excepted: which tile
POV-Ray gives them is not modelled).
"""
import math
import sys

S3 = math.sqrt(3)
H = S3 / 2


def e(deg):
    return (math.cos(math.radians(deg)), math.sin(math.radians(deg)))


def add(*ps):
    return (sum(p[0] for p in ps), sum(p[1] for p in ps))


def sc(p, k):
    return (p[0] * k, p[1] * k)


def at(c, deg, r):
    """The point at distance r from c in direction deg."""
    return add(c, sc(e(deg), r))


def reg(n, c, side, deg):
    """A regular n-gon with centre c, the given side, a vertex at angle deg."""
    r = side / (2 * math.sin(math.pi / n))
    a = math.radians(deg)
    return [(c[0] + r * math.cos(a + 2 * math.pi * k / n), c[1] + r * math.sin(a + 2 * math.pi * k / n))
            for k in range(n)]


def tri(c, up):
    """A unit equilateral triangle with centre c, pointing to +z (up) or -z."""
    return reg(3, c, 1, 90 if up else 270)


def rect(x0, z0, x1, z1):
    return [(x0, z0), (x1, z0), (x1, z1), (x0, z1)]


def rhomb(c, a1, a2):
    """A unit rhombus with corner c and sides along the angles a1, a2."""
    u, w = e(a1), e(a2)
    return [c, add(c, u), add(c, u, w), add(c, w)]


def lattice_tris(a, b, origin, exclude):
    """The unit triangles of the triangular lattice (a vertex at the origin,
    edges along x) whose centre lies in the cell spanned by a and b at
    origin, except those whose centre makes exclude() true."""
    det = a[0] * b[1] - a[1] * b[0]
    out = []
    for j in range(-12, 13):
        for i in range(-12, 13):
            for up in (True, False):
                cx = i + j * 0.5 + (0.5 if up else 1.0)
                cz = j * H + (H / 3 if up else 2 * H / 3)
                px, pz = cx - origin[0], cz - origin[1]
                u = (b[1] * px - b[0] * pz) / det
                w = (-a[1] * px + a[0] * pz) / det
                if 0 <= u < 1 and 0 <= w < 1 and not exclude((cx, cz)):
                    out.append((0 if up else 1, tri((cx, cz), up)))
    return out


# ---- the tilings: (a, b, N, [(type, polygon[, wide edges]), ...]) ----

def t1():
    return (1, 0), (0, 1), 1, [(0, rect(0, 0, 1, 1))]


def t2():
    return (3, 0), (1.5, H), 1, [(0, reg(6, (-1, 0), 1, 0))]


def t3():
    return (1, 0), (0.5, H), 2, [(0, [(0, 0), (1, 0), (0.5, H)]), (1, [(0, 0), (0.5, H), (-0.5, H)])]


def t4():
    return (1, 0), (0.5, H), 1, [(0, [(-1, 0), (0, 0), (0.5, H), (-0.5, H)])]


def t5():
    c = (1, 0)
    return (0, S3), (1.5, H), 3, [(1, rhomb(c, -60, 60)), (0, rhomb(c, 60, 180)), (2, rhomb(c, 180, 300))]


def t6():
    return (1, 1), (-1, 3), 2, [(0, rect(-1, -2, 1, -1)), (1, rect(-2, -2, -1, 0))]


def t7():
    w = 1 + math.sqrt(2)
    return (w, 0), (0, w), 2, [(1, reg(8, (0, 0), 1, 22.5)), (0, reg(4, (w / 2, w / 2), 1, 0))]


def t8():
    return (1, 0), (0.5, 1 + H), 3, [(2, rect(0, 0, 1, 1)), (0, [(0, 1), (1, 1), (0.5, 1 + H)]),
                                     (1, [(1, 1), (1.5, 1 + H), (0.5, 1 + H)])]


def t9():
    return (1, S3), (2, 0), 3, [(2, reg(6, (0.5, H), 1, 0)), (0, [(-1, 0), (0, 0), (-0.5, H)]),
                                (1, [(0, 0), (0.5, -H), (1, 0)])]


def t10():
    return (1, 0), (0.5, 1), 1, [(0, rect(0, 0, 1, 1))]


def t11():
    return (3, 0), (0, 3), 3, [(0, rect(1, 1, 2, 2)), (1, rect(-2, 0, 0, 1)), (1, rect(0, -1, 2, 0)),
                               (2, rect(0, 0, 1, 2)), (2, rect(-1, -2, 0, 0))]


def t12():
    return (3, 3), (-3, 3), 3, [
        (0, rect(1, 1, 2, 2)), (0, rect(1, -2, 2, -1)),
        (2, rect(-1, -2, 0, 0)), (2, rect(0, -2, 1, 0)), (2, rect(-1, 0, 0, 2)), (2, rect(0, 0, 1, 2)),
        (1, rect(1, -1, 3, 0)), (1, rect(3, -1, 5, 0)), (1, rect(1, 0, 3, 1)), (1, rect(3, 0, 5, 1))]


def squares_and_trapezoids(types):
    """Tilings 13 and 14: squares of side sqrt 2 among trapezoids; types
    (square, upper, lower, right, left)."""
    s = math.sqrt(2) / 2
    l = 4 * s
    sq, up, lo, ri, le = types
    return (l, 0), (0, l), max(types) + 1, [
        (sq, rect(s, s, 3 * s, 3 * s)),
        (up, [(0, 0), (l, 0), (l - s, s), (s, s)]), (lo, [(0, 0), (s, -s), (l - s, -s), (l, 0)]),
        (ri, [(0, 0), (s, s), (s, l - s), (0, l)]), (le, [(0, 0), (0, l), (-s, l - s), (-s, s)])]


def t13():
    return squares_and_trapezoids((0, 1, 1, 2, 2))


def t14():
    return squares_and_trapezoids((4, 2, 3, 1, 0))


def t15():
    return (2, 1), (1, -2), 2, [(0, rect(0, 0, 1, 1)), (1, rect(-1, -2, 1, 0))]


def rhombitrihexagonal(n, hexa, squares, tris):
    """Tilings 16 and 17 (3.4.6.4): a hexagon at (-1, 0), squares at the
    given directions (angle, type), triangles at the given corners."""
    a = 1 + S3
    c = (-1, 0)
    return (sc(e(30), a), sc(e(-30), a), n,
            [(hexa, reg(6, c, 1, 0))] +
            [(ty, reg(4, at(c, t, H + 0.5), 1, t + 45)) for t, ty in squares] +
            [(ty, reg(3, at(c, t, 1 + 1 / S3), 1, t + 180)) for t, ty in tris])


def t16():
    return rhombitrihexagonal(3, 2, ((30, 0), (90, 0), (150, 0)), ((0, 1), (60, 1)))


def t17():
    return rhombitrihexagonal(6, 5, ((30, 1), (90, 0), (150, 2)), ((0, 4), (60, 3)))


def t18():
    return (2, 2), (2, -2), 2, [(0, rect(-2, 0, 0, 1)), (0, rect(-2, 1, 0, 2)),
                                (1, rect(0, 0, 1, 2)), (1, rect(1, 0, 2, 2))]


def hexagons_in_triangles(a, b, c):
    """Tilings 19 and 20: unit triangles (up 0, down 1) with one hexagon
    (type 2) per cell, centred at c."""
    def in_hexagon(p):
        for i in range(-3, 4):
            for j in range(-3, 4):
                hx = c[0] + i * a[0] + j * b[0]
                hz = c[1] + i * a[1] + j * b[1]
                if math.hypot(p[0] - hx, p[1] - hz) < 0.7:
                    return True
        return False
    return a, b, 3, [(2, reg(6, c, 1, 0))] + lattice_tris(a, b, (c[0] - 0.01, c[1] + 0.01), in_hexagon)


def t19():
    return hexagons_in_triangles((2.5, -H), (2, S3), (-1, 0))


def t20():
    return hexagons_in_triangles((2.5, H), (0.5, 3 * H), (0.5, -H))


def t21():
    k = (1 + S3) / 2
    return (k, k), (k, -k), 6, [
        (4, [(0, 0.5), (H, 0), (k, H), (0.5, k)]), (5, [(0, -0.5), (0.5, -k), (k, -H), (H, 0)]),
        (0, [(0, 0.5), (0, -0.5), (H, 0)]), (2, [(0, 0.5), (-H, 0), (0, -0.5)]),
        (1, [(0, 0.5), (0.5, k), (-0.5, k)]), (3, [(0, -0.5), (-0.5, -k), (0.5, -k)])]


def t22():
    a = 1 + H  # the dodecagon's apothem
    rt = 1 / (2 * S3)
    # Measured: the dodecagon's edges facing +x, -x and -z are bevelled
    # 1/3 wide, its others as wide as the triangles' inradius.
    return (2 * a, 0), (a, S3 * a), 3, [
        (2, reg(12, (0, 0.5 - a), 1, 15), {0: 1 / 3, 180: 1 / 3, 270: 1 / 3}),
        (0, tri((0, 0.5 + rt), True)), (1, tri((a, -rt), False))]


def truncated_trihexagonal(n, dodeca, squares, hexa):
    """Tilings 23 and 24 (4.6.12): a dodecagon, squares at the given
    directions (angle, type), hexagons of the given type."""
    a = 1 + H
    c = (0, 0.5 - a)
    d = 2 * (a + 0.5)
    return ((d, 0), sc(e(60), d), n,
            [(dodeca, reg(12, c, 1, 15))] +
            [(ty, reg(4, at(c, t, a + 0.5), 1, t + 45)) for t, ty in squares] +
            [(hexa, reg(6, at(c, t, a + H), 1, 0)) for t in (30, 90)])


def t23():
    return truncated_trihexagonal(3, 2, ((0, 1), (60, 1), (120, 1)), 0)


def t24():
    return truncated_trihexagonal(5, 4, ((0, 1), (60, 2), (120, 3)), 0)


TILINGS = {i: globals()["t%d" % i] for i in range(1, 28) if ("t%d" % i) in globals()}

# ---- from polygons to edges ----


def area(v):
    return 0.5 * sum(v[i][0] * v[(i + 1) % len(v)][1] - v[(i + 1) % len(v)][0] * v[i][1] for i in range(len(v)))


def edges(v):
    """(nx, nz, off, angle): the outward unit normal and offset of each
    edge (inside: nx x + nz z < off), and the normal's angle in degrees."""
    if area(v) < 0:
        v = v[::-1]
    out = []
    for i in range(len(v)):
        (x0, z0), (x1, z1) = v[i], v[(i + 1) % len(v)]
        dx, dz = x1 - x0, z1 - z0
        ln = math.hypot(dx, dz)
        nx, nz = dz / ln, -dx / ln
        out.append((nx, nz, nx * x0 + nz * z0, round(math.degrees(math.atan2(nz, nx))) % 360))
    return out


def clip(poly, nx, nz, off):
    out = []
    for i in range(len(poly)):
        p, q = poly[i], poly[(i + 1) % len(poly)]
        dp = off - (nx * p[0] + nz * p[1])
        dq = off - (nx * q[0] + nz * q[1])
        if dp >= 0:
            out.append(p)
        if (dp >= 0) != (dq >= 0):
            t = dp / (dp - dq)
            out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    return out


def inradius(v):
    """The radius of the largest circle inside the convex polygon v."""
    E = edges(v)
    lo, hi = 0.0, 10.0
    for _ in range(100):
        r = (lo + hi) / 2
        p = [(-1e3, -1e3), (1e3, -1e3), (1e3, 1e3), (-1e3, 1e3)]
        for nx, nz, off, _ in E:
            p = clip(p, nx, nz, off - r)
            if not p:
                break
        if p:
            lo = r
        else:
            hi = r
    return lo


class Tiling:
    """A tiling ready to evaluate: polygons moved into the cell, edges with
    the reciprocal of their bevel width."""

    def __init__(self, a, b, n, polys):
        self.a, self.b, self.n = a, b, n
        det = a[0] * b[1] - a[1] * b[0]
        self.inv = (b[1] / det, -b[0] / det, -a[1] / det, a[0] / det)
        placed = []
        for item in polys:
            t, v = item[0], item[1]
            wide = item[2] if len(item) > 2 else {}
            cx = sum(p[0] for p in v) / len(v)
            cz = sum(p[1] for p in v) / len(v)
            u = math.floor(self.inv[0] * cx + self.inv[1] * cz + 1e-9)
            w = math.floor(self.inv[2] * cx + self.inv[3] * cz + 1e-9)
            v = [(p[0] - u * a[0] - w * b[0], p[1] - u * a[1] - w * b[1]) for p in v]
            placed.append((t, v, wide))
        self.rho = min(inradius(v) for _, v, _ in placed)
        self.polys = [(t, [(nx, nz, off, 1.0 / wide.get(ang, self.rho)) for nx, nz, off, ang in edges(v)])
                      for t, v, wide in placed]

    def value(self, x, z):
        """The value at (x, z) and whether the point is on a boundary."""
        u = math.floor(self.inv[0] * x + self.inv[1] * z)
        w = math.floor(self.inv[2] * x + self.inv[3] * z)
        x0 = x - u * self.a[0] - w * self.b[0]
        z0 = z - u * self.a[1] - w * self.b[1]
        best, rel, typ, near = -1e9, 0.0, 0, 0
        for i in (-1, 0, 1):
            for j in (-1, 0, 1):
                px = x0 - i * self.a[0] - j * self.b[0]
                pz = z0 - i * self.a[1] - j * self.b[1]
                for t, E in self.polys:
                    d = min(off - (nx * px + nz * pz) for nx, nz, off, _ in E)
                    if abs(d) < 1e-9:
                        near += 1
                    if d > best:
                        best, typ = d, t
                        rel = min((off - (nx * px + nz * pz)) * ir for nx, nz, off, ir in E)
        return (typ + 1 - min(rel, 1.0)) / self.n, near > 1


def check(directory):
    bad = 0
    for k, f in sorted(TILINGS.items()):
        t = Tiling(*f())
        worst = 0.0
        for line in open("%s/t%d.txt" % (directory, k)):
            x, z, v = map(float, line.split())
            m, edge = t.value(x, z)
            if not edge:
                worst = max(worst, abs(m - v))
        print("tiling %2d: max difference %.3g" % (k, worst))
        bad += worst > 1e-5
    return bad


def emit():
    w = sys.stdout.write
    w("/* tiling_table.c: the tiles of POV-Ray's `tiling N` patterns (see\n"
      " * tiling_table.h). GENERATED by tiling_gen.py from the measured geometry\n"
      " * there: edit that, not this. */\n#include \"pattern/tiling_table.h\"\n\n")
    order = sorted(TILINGS)
    for k in order:
        t = Tiling(*TILINGS[k]())
        w("static const struct tile_edge edges%d[] = {\n" % k)
        for _, E in t.polys:
            for ed in E:
                w("\t{%.17g, %.17g, %.17g, %.17g},\n" % ed)
        w("};\n")
        w("static const struct tile_poly polys%d[] = {" % k)
        start = 0
        items = []
        for typ, E in t.polys:
            items.append("{%d, %d, %d}" % (typ, start, len(E)))
            start += len(E)
        w(", ".join(items) + "};\n\n")
    w("const struct tiling_def tiling_defs[TILING_COUNT] = {\n")
    for k in range(1, 28):
        if k not in TILINGS:
            w("\t{0, {0, 0}, {0, 0}, {0, 0, 0, 0}, 0, 0, 0},\n")
            continue
        t = Tiling(*TILINGS[k]())
        w("\t{%d, {%.17g, %.17g}, {%.17g, %.17g}, {%.17g, %.17g, %.17g, %.17g}, %d, polys%d, edges%d},\n"
          % (t.n, t.a[0], t.a[1], t.b[0], t.b[1], t.inv[0], t.inv[1], t.inv[2], t.inv[3], len(t.polys), k, k))
    w("};\n")


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--check":
        sys.exit(1 if check(sys.argv[2]) else 0)
    emit()

#!/usr/bin/python3
"""tests/stability/check.py: the property checks of tests/stability/run.sh
that idiff cannot do, one subcommand each:

  range IMAGE [--max M]
      no NaN or infinite value, none below 0 (nor above M).
  speckles IMAGE [--thr T] [--row R]... [--col C]...
      along each given row (column), no pixel that differs by more than T
      from both its neighbours along the row (column) while those two
      agree within T; with no row or column, no pixel of the image that
      differs by more than T from all eight of its neighbours.
  dark IMAGE REF [--thr T]
      no pixel darker than in REF by more than T (mean of the channels).
  flat IMAGE --bg C [--black] [--below [--max-loss M]] [--tol T]
      every pixel is the colour C (within T, default 2e-3); with --black,
      or black (every channel within T of 0); with --below, any pixel
      with no channel above C's by more than T, and a mean loss
      (1 - pixel/C, over the channels and pixels) of at most M.
  subset IMAGE REF [--tol T]
      every pixel that is black in REF is black in IMAGE (REF rendered
      with a higher max_trace_level than IMAGE).
  grazing IMAGE --bg C --floor C --kmin K --kmax K [--horizon ROW]
      every pixel is the background colour or the floor colour times a
      factor in [kmin, kmax]; down each column, background then floor,
      whose factor never decreases; with --horizon, every row above ROW
      background and every row below it floor.
  torus IMAGE --bg C --camera CAM --R R --r r
      a pixel shows the torus (axis y, centred at the origin) if and only
      if its ray passes within r of the circle of radius R.
  inside IMAGE --bg C --camera CAM [--sphere X,Y,Z,RIN,ROUT]... [--rect Z,X0,Y0,X1,Y1]...
      every pixel whose ray passes within RIN of a sphere's centre or
      through the rectangle (in the plane z = Z) is not background, and
      every pixel whose ray misses all of them (ROUT, the rectangle's
      border) is background.

Colours are "r,g,b"; components may be simple expressions ("4/3"). For
torus and inside, --bg defaults to the colour of the top left pixel.
CAM is "LOCATION;DIRECTION;RIGHT;UP", four vectors: pixel (i, j) of a
W x H image looks along DIRECTION + ((i + 0.5)/W - 0.5) RIGHT
+ (0.5 - (j + 0.5)/H) UP, as POV-Ray's perspective camera does.

Images are read through OpenImageIO's `oiiotool --dumpdata`, so PNG and
OpenEXR both do: PNG values are the stored ones (gamma-encoded) in
[0, 1], OpenEXR values linear and unclamped. A pixel is background when
no channel is farther than --bgtol (default 0.02) from the background.

Each command prints one line of figures and exits 0 when the property
holds, 1 when it does not, 2 on a usage or read error.
"""
import argparse
import subprocess
import sys

import numpy as np


def load(path):
    """Return the image at `path` as a float array [height, width, channels]."""
    try:
        out = subprocess.run(['oiiotool', '--dumpdata', path], capture_output=True,
                             text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError) as e:
        print('check.py: cannot read %s: %s' % (path, e), file=sys.stderr)
        sys.exit(2)
    lines = out.splitlines()
    # "name : 160 x 120, 3 channel, uint8 png"
    size = lines[0].split(':', 1)[1].split(',')[0].split('x')
    width, height = int(size[0]), int(size[1])
    vals = []
    for ln in lines[1:]:
        if 'Pixel (' not in ln:
            continue
        s = ln.split(':', 1)[1]
        # 8-bit images give "124 149 203 (0.486 0.584 0.796)": the floats.
        if '(' in s:
            s = s[s.index('(') + 1:s.rindex(')')]
        vals.append([float(v) for v in s.split()])
    img = np.array(vals, dtype=float)
    return img.reshape(height, width, -1)[:, :, :3]


def number(s):
    """A float from a number or a simple arithmetic expression."""
    if not set(s) <= set('0123456789.+-*/eE() '):
        raise argparse.ArgumentTypeError('not a number: %r' % s)
    return float(eval(s, {'__builtins__': {}}))  # digits and operators only


def vector(s):
    return np.array([number(c) for c in s.split(',')])


def camera(s):
    parts = [vector(v) for v in s.split(';')]
    if len(parts) != 4 or any(len(p) != 3 for p in parts):
        raise argparse.ArgumentTypeError('camera is LOCATION;DIRECTION;RIGHT;UP')
    return parts


def rays(cam, width, height):
    """Directions of the pixels' rays, [height, width, 3]."""
    _, direction, right, up = cam
    u = (np.arange(width) + 0.5) / width - 0.5
    v = 0.5 - (np.arange(height) + 0.5) / height
    return direction + u[None, :, None] * right + v[:, None, None] * up


def differ(a, b, thr):
    return np.abs(a - b).max(axis=-1) > thr


def background(img, bg, tol):
    return ~differ(img, bg, tol)


def positions(mask, limit=6):
    ys, xs = np.nonzero(mask)
    pts = ' '.join('(%d,%d)' % p for p in list(zip(xs, ys))[:limit])
    return pts + (' ...' if len(xs) > limit else '')


def cmd_range(a):
    img = load(a.image)
    nan = int(np.isnan(img).sum())
    inf = int(np.isinf(img).sum())
    fin = img[np.isfinite(img)]
    lo, hi = (fin.min(), fin.max()) if fin.size else (0.0, 0.0)
    bad = nan + inf + int((fin < 0).sum())
    if a.max is not None:
        bad += int((fin > a.max).sum())
    print('%d NaN, %d infinite, min %.6g, max %.6g' % (nan, inf, lo, hi))
    return bad == 0


def cmd_speckles(a):
    img = load(a.image)
    t = a.thr
    found = np.zeros(img.shape[:2], bool)
    for r in a.row:
        row = img[r]
        mid, left, right = row[1:-1], row[:-2], row[2:]
        found[r, 1:-1] |= differ(mid, left, t) & differ(mid, right, t) & ~differ(left, right, t)
    for c in a.col:
        col = img[:, c]
        mid, up, down = col[1:-1], col[:-2], col[2:]
        found[1:-1, c] |= differ(mid, up, t) & differ(mid, down, t) & ~differ(up, down, t)
    if not a.row and not a.col:
        mid = img[1:-1, 1:-1]
        iso = np.ones(mid.shape[:2], bool)
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                if dy or dx:
                    nb = img[1 + dy:img.shape[0] - 1 + dy, 1 + dx:img.shape[1] - 1 + dx]
                    iso &= differ(mid, nb, t)
        found[1:-1, 1:-1] = iso
    n = int(found.sum())
    print('%d speckle%s (threshold %g)%s' % (n, '' if n == 1 else 's', t,
                                             ': ' + positions(found) if n else ''))
    return n == 0


def cmd_dark(a):
    img, ref = load(a.image), load(a.ref)
    dark = ref.mean(axis=-1) - img.mean(axis=-1) > a.thr
    n = int(dark.sum())
    print('%d pixel%s darker than the reference by more than %g%s'
          % (n, '' if n == 1 else 's', a.thr, ': ' + positions(dark) if n else ''))
    return n == 0


def black(img, tol):
    return np.abs(img).max(axis=-1) <= tol


def cmd_flat(a):
    img = load(a.image)
    t = a.tol
    nblack = black(img, t)
    if a.below:
        ratio = img / a.bg
        bad = (img > a.bg + t).any(axis=-1)
        loss = float((1 - ratio).mean())
        print('%d pixel%s brighter than the colour, mean loss %.5f (at most %g), '
              'darkest pixel %.4f of the colour%s'
              % (int(bad.sum()), '' if bad.sum() == 1 else 's', loss, a.max_loss,
                 float(ratio.min()), ': ' + positions(bad) if bad.any() else ''))
        return not bad.any() and loss <= a.max_loss
    bad = differ(img, a.bg, t)
    if a.black:
        bad &= ~nblack
    print('%d pixels the colour, %d black%s, %d other%s'
          % (int((~differ(img, a.bg, t)).sum()), int(nblack.sum()),
             '' if a.black else ' (not allowed)', int(bad.sum()),
             ': ' + positions(bad) if bad.any() else ''))
    return not bad.any()


def cmd_subset(a):
    img, ref = load(a.image), load(a.ref)
    bi, br = black(img, a.tol), black(ref, a.tol)
    bad = br & ~bi
    print('%d black pixels, %d in the reference, %d black there and not here%s'
          % (int(bi.sum()), int(br.sum()), int(bad.sum()),
             ': ' + positions(bad) if bad.any() else ''))
    return not bad.any()


def cmd_grazing(a):
    img = load(a.image)
    tol = a.tol
    isbg = background(img, a.bg, tol)
    f = a.floor
    k = (img @ f) / (f @ f)
    resid = np.abs(img - k[..., None] * f).max(axis=-1)
    isfloor = ~isbg & (resid <= tol) & (k >= a.kmin - tol) & (k <= a.kmax + tol)
    other = ~isbg & ~isfloor
    # Down each column: no background under a floor pixel, and the floor's
    # factor never decreases by more than the tolerance.
    below = np.maximum.accumulate(isfloor, axis=0)
    order = isbg & below
    kk = np.where(isfloor, k, np.nan)
    dips = np.zeros(img.shape[:2], bool)
    dips[1:] = isfloor[1:] & isfloor[:-1] & (kk[1:] < kk[:-1] - tol)
    horizon = np.zeros(img.shape[:2], bool)
    if a.horizon is not None:
        horizon[:a.horizon] = ~isbg[:a.horizon]
        horizon[a.horizon + 1:] = ~isfloor[a.horizon + 1:]
    nfloor = int(isfloor.sum())
    print('%d background, %d floor (factor %.4g to %.4g), %d other colour, %d background '
          'under floor, %d dips, %d off the horizon%s'
          % (int(isbg.sum()), nfloor, np.nanmin(kk) if nfloor else 0,
             np.nanmax(kk) if nfloor else 0, int(other.sum()), int(order.sum()),
             int(dips.sum()), int(horizon.sum()),
             ': ' + positions(other | order | dips | horizon)
             if (other | order | dips | horizon).any() else ''))
    return not (other | order | dips | horizon).any()


def cmd_torus(a):
    img = load(a.image)
    height, width = img.shape[:2]
    hit = ~background(img, img[0, 0] if a.bg is None else a.bg, a.bgtol)
    org = a.camera[0]
    d = rays(a.camera, width, height).reshape(-1, 3)
    big, small = a.R, a.r
    dist = np.full(len(d), np.inf)
    # The tube lies within |y| <= r: look only along that stretch of each
    # ray, and only at rays whose crossing of y = 0 is near the circle.
    dy = d[:, 1]
    down = np.abs(dy) > 1e-12
    sdy = np.where(down, dy, 1.0)
    t0 = -org[1] / sdy
    half = 2 * small / np.abs(sdy)
    p0 = org + t0[:, None] * d
    reach = half * np.hypot(d[:, 0], d[:, 2])
    near = down & (t0 + half > 0) & (np.abs(np.hypot(p0[:, 0], p0[:, 2]) - big) < reach + 2 * small)
    idx = np.nonzero(near)[0]

    def closest(dd, lo, hi, n):
        t = lo[:, None] + (hi - lo)[:, None] * np.linspace(0, 1, n)[None, :]
        p = org + t[:, :, None] * dd[:, None, :]
        f = (np.hypot(p[..., 0], p[..., 2]) - big) ** 2 + p[..., 1] ** 2
        i = f.argmin(axis=1)
        return t[np.arange(len(i)), i], f.min(axis=1)

    if len(idx):
        dd = d[idx]
        lo = np.maximum(t0[idx] - half[idx], 0)
        hi = t0[idx] + half[idx]
        tm, _ = closest(dd, lo, hi, 4001)
        step = (hi - lo) / 4000
        _, fm = closest(dd, np.maximum(tm - step, 0), tm + step, 1001)
        dist[idx] = np.sqrt(fm)
    dist = dist.reshape(height, width)
    unsure = np.abs(dist - small) < 1e-3 * small
    expect = dist < small
    wrong = (expect != hit) & ~unsure
    missed = wrong & expect
    extra = wrong & ~expect
    print('%d pixels show the torus, %d expected, %d missed, %d stray, %d too close to call%s'
          % (int(hit.sum()), int(expect.sum()), int(missed.sum()), int(extra.sum()),
             int(unsure.sum()), ': ' + positions(wrong) if wrong.any() else ''))
    return not wrong.any()


def cmd_inside(a):
    img = load(a.image)
    height, width = img.shape[:2]
    isbg = background(img, img[0, 0] if a.bg is None else a.bg, a.bgtol)
    org = a.camera[0]
    d = rays(a.camera, width, height)
    m = a.margin
    shapes = []
    for s in a.sphere:
        c, rin, rout = s[:3], s[3], s[4]
        # distance from the centre to the ray's line (the camera is outside)
        oc = c - org
        t = (d @ oc) / (d * d).sum(-1)
        dist = np.linalg.norm(t[..., None] * d - oc, axis=-1)
        shapes.append(('sphere at <%g,%g,%g>' % tuple(c), dist < rin * (1 - m),
                       dist < rout * (1 + m)))
    for r in a.rect:
        z, x0, y0, x1, y1 = r
        t = (z - org[2]) / d[..., 2]
        x = org[0] + t * d[..., 0]
        y = org[1] + t * d[..., 1]
        e = m * max(x1 - x0, y1 - y0)
        shapes.append(('rectangle at z=%g' % z,
                       (t > 0) & (x > x0 + e) & (x < x1 - e) & (y > y0 + e) & (y < y1 - e),
                       (t > 0) & (x > x0 - e) & (x < x1 + e) & (y > y0 - e) & (y < y1 + e)))
    must = np.zeros(isbg.shape, bool)
    may = np.zeros(isbg.shape, bool)
    holes = []
    for name, inner, outer in shapes:
        must |= inner
        may |= outer
        holes.append('%s %d' % (name, int((inner & isbg).sum())))
    hole = must & isbg
    stray = ~may & ~isbg
    print('%d pixels must show a mesh: %d holes (%s); %d stray hits%s'
          % (int(must.sum()), int(hole.sum()), ', '.join(holes), int(stray.sum()),
             ': ' + positions(hole | stray) if (hole | stray).any() else ''))
    return not (hole | stray).any()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest='cmd', required=True)

    p = sub.add_parser('range')
    p.add_argument('image')
    p.add_argument('--max', type=number)
    p.set_defaults(run=cmd_range)

    p = sub.add_parser('speckles')
    p.add_argument('image')
    p.add_argument('--thr', type=number, default=0.1)
    p.add_argument('--row', type=int, action='append', default=[])
    p.add_argument('--col', type=int, action='append', default=[])
    p.set_defaults(run=cmd_speckles)

    p = sub.add_parser('dark')
    p.add_argument('image')
    p.add_argument('ref')
    p.add_argument('--thr', type=number, default=0.1)
    p.set_defaults(run=cmd_dark)

    p = sub.add_parser('flat')
    p.add_argument('image')
    p.add_argument('--bg', type=vector, required=True)
    p.add_argument('--black', action='store_true')
    p.add_argument('--below', action='store_true')
    p.add_argument('--max-loss', type=number, default=0)
    p.add_argument('--tol', type=number, default=2e-3)
    p.set_defaults(run=cmd_flat)

    p = sub.add_parser('subset')
    p.add_argument('image')
    p.add_argument('ref')
    p.add_argument('--tol', type=number, default=2e-3)
    p.set_defaults(run=cmd_subset)

    p = sub.add_parser('grazing')
    p.add_argument('image')
    p.add_argument('--bg', type=vector, required=True)
    p.add_argument('--floor', type=vector, required=True)
    p.add_argument('--kmin', type=number, required=True)
    p.add_argument('--kmax', type=number, required=True)
    p.add_argument('--horizon', type=int)
    p.add_argument('--tol', type=number, default=2e-3)
    p.set_defaults(run=cmd_grazing)

    for name, run in (('torus', cmd_torus), ('inside', cmd_inside)):
        p = sub.add_parser(name)
        p.add_argument('image')
        p.add_argument('--bg', type=vector)
        p.add_argument('--bgtol', type=number, default=0.02)
        p.add_argument('--camera', type=camera, required=True)
        p.set_defaults(run=run)
        if name == 'torus':
            p.add_argument('--R', type=number, required=True)
            p.add_argument('--r', type=number, required=True)
        else:
            p.add_argument('--sphere', type=vector, action='append', default=[])
            p.add_argument('--rect', type=vector, action='append', default=[])
            p.add_argument('--margin', type=number, default=1e-3)

    a = ap.parse_args()
    sys.exit(0 if a.run(a) else 1)


if __name__ == '__main__':
    main()

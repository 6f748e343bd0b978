#!/bin/sh
# fn_internal_sweep.sh: compares lucent's internal functions with POV-Ray
# 3.7's on random cases. A tool for finding differences, not part of
# `make check`: it needs povray and python3 on the PATH (POVRAY and LUCENT
# override the commands; LUCENT defaults to the built ./lucent).
#
#   sh tests/unit/fn_internal_sweep.sh [SEED [COUNT [N ...]]]
#       COUNT random cases (default 300) for each internal function N
#       (default: every one but the noise-based 29, 58, 59, 76, 78):
#       points in [-4,4]^3 (a few on the axes or at half-integers) and
#       parameters from a mix of uniform [-4,4] and [0,3], integers -3..6,
#       halves, zero, tiny values (1e-6..0.1, either sign), [-50,50] and
#       [-360,360]. With SPECIAL=1 in the environment a quarter of the
#       parameters are 0 and many more are +-1, small integers or halves
#       (counts, switches and types at their edges).
#   sh tests/unit/fn_internal_sweep.sh -
#       reads cases "N x y z P0 P1 ..." from standard input instead and
#       prints both values for each.
#
# Each case is evaluated by POV-Ray and lucent running the same scene
# (one scene per function; POV-Ray's start-up is slow), which prints
# mantissa and exponent exactly, and the sign of a zero and of a NaN.
# A case differs when the two are more than TOL (default 1e-12) apart
# relative to the larger, or are not both NaN or the same infinity, or
# are zeros or NaNs of different signs. For each function the report
# gives the cases, how many are bit-identical and how many differ, the
# largest relative difference among finite values, and the first few
# differing cases.
here=$(cd "$(dirname "$0")" && pwd) || exit 1
top=$(cd "$here/../.." && pwd) || exit 1
export FNSRC="$top/src/scene/fn_internal.c"
export LUCENT="${LUCENT:-$top/lucent}"
export POVRAY="${POVRAY:-povray}"
prog=$(cat <<'EOF'
import math, os, random, re, subprocess, sys, tempfile

src = open(os.environ['FNSRC']).read()
table = src[src.index('internal_defs[] = {'):]
defs = re.findall(r'\{"([^"]*)", (\d+), \w+\}', table)
NAMES = [d[0] for d in defs]
NPARAMS = [int(d[1]) for d in defs]
NOISE = {29, 58, 59, 76, 78}
TOL = float(os.environ.get('TOL', '1e-12'))

def rparam(rng):
    r = rng.random()
    if r < 0.35: return round(rng.uniform(-4, 4), 4)
    if r < 0.50: return round(rng.uniform(0, 3), 4)
    if r < 0.65: return rng.randint(-3, 6)
    if r < 0.72: return 0
    if r < 0.80: return rng.randint(-6, 12) / 2
    if r < 0.88: return round(rng.choice([-1, 1]) * 10 ** rng.uniform(-6, -1), 9)
    if r < 0.95: return round(rng.uniform(-50, 50), 3)
    return round(rng.uniform(-360, 360), 2)

def rspecial(rng):
    r = rng.random()
    if r < 0.25: return 0
    if r < 0.40: return rng.choice([-1, 1])
    if r < 0.50: return rng.randint(-3, 6)
    if r < 0.60: return rng.randint(-6, 12) / 2
    return rparam(rng)

def rcoord(rng):
    r = rng.random()
    if r < 0.06: return 0
    if r < 0.10: return rng.randint(-4, 4) / 2
    return round(rng.uniform(-4, 4), 4)

# P prints a binary mantissa (to 20 decimals, which decode exactly) and
# exponent, the sign, 1/v for a zero (its sign) and v * 0 (a NaN's sign),
# computed by functions so that NaN and inf pass through. Scaling by a
# power of 2 is exact, so bit-identical values compare equal.
HEAD = r'''#version 3.7;
#declare FE = function(v) { floor(ln(abs(v)) / ln(2)) }
#declare FM = function(v) { v * pow(2, -floor(ln(abs(v)) / ln(2))) }
#declare FS = function(v) { select(v, -1, 0, 1) }
#declare FZ = function(v) { select(v, 0, 1/v, 0) }
#declare FN = function(v) { v * 0 }
#macro P(V) #debug concat(str(FM(V),0,20), " ", str(FE(V),0,0), " ",
  str(FS(V),0,0), " ", str(FZ(V),0,0), " ", str(FN(V),0,0), "\n") #end
'''

def text(v):
    return repr(v) if isinstance(v, float) else str(v)

def decode(line):
    m, e, s, zs, ns = line.split()
    if zs in ('inf', '-inf'): return ('zero', zs)
    if 'nan' in e: return ('nan', ns)
    if e == 'inf': return float(s) * math.inf
    if e == '-inf': return 0.0
    return math.ldexp(float(m), int(e))

def run(cmd, work, name):
    subprocess.run([cmd, '-D', '-F', '+W8', '+H8', '+GD' + name + '.dbg', '+I' + name + '.pov'],
                   cwd=work, capture_output=True)
    path = os.path.join(work, name + '.dbg')
    if not os.path.exists(path):
        sys.exit('fn_internal_sweep.sh: %s printed nothing for %s.pov' % (cmd, name))
    return [decode(l) for l in open(path) if l.strip()]

def evaluate(cases, work, name):
    with open(os.path.join(work, name + '.pov'), 'w') as f:
        f.write(HEAD)
        for n in sorted({c[0] for c in cases}):
            f.write('#declare F%d = function { internal(%d) }\n' % (n, n))
        for n, args in cases:
            f.write('P(F%d(%s))\n' % (n, ', '.join(text(a) for a in args)))
    pov = run(os.environ['POVRAY'], work, name)
    luc = run(os.environ['LUCENT'], work, name)
    if not len(pov) == len(luc) == len(cases):
        sys.exit('fn_internal_sweep.sh: value counts differ in %s.pov' % name)
    return list(zip(cases, pov, luc))

def same(a, b):
    if isinstance(a, tuple) or isinstance(b, tuple): return a == b
    if math.isinf(a) or math.isinf(b): return a == b
    return abs(a - b) <= TOL * max(abs(a), abs(b))

def show(v):
    return '%s(%s)' % v if isinstance(v, tuple) else '%.17g' % v

work = tempfile.mkdtemp(prefix='fn_internal_sweep.')
try:
    if sys.argv[1:2] == ['-']:
        cases = []
        for line in sys.stdin:
            w = line.split('#')[0].split()
            if w: cases.append((int(w[0]), [float(v) for v in w[1:]]))
        for c, p, l in evaluate(cases, work, 'cases'):
            print('%-60s pov %s  lucent %s%s' % (' '.join(text(a) for a in c[1]),
                  show(p), show(l), '' if same(p, l) else '  DIFF'))
        sys.exit(0)
    seed = int(sys.argv[1]) if len(sys.argv) > 1 else 1
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 300
    fns = [int(a) for a in sys.argv[3:]] or [n for n in range(len(NAMES)) if n not in NOISE]
    rng = random.Random(seed)
    gen = rspecial if os.environ.get('SPECIAL') else rparam
    for n in fns:
        cases = [(n, [rcoord(rng) for _ in range(3)] + [gen(rng) for _ in range(NPARAMS[n] - 3)])
                 for _ in range(count)]
        res = evaluate(cases, work, 'f%d' % n)
        bad = [r for r in res if not same(r[1], r[2])]
        exact = sum(1 for c, p, l in res if p == l or (p != p and l != l))
        worst = max((abs(p - l) / max(abs(p), abs(l)) for c, p, l in res
                     if not isinstance(p, tuple) and not isinstance(l, tuple)
                     and math.isfinite(p) and math.isfinite(l) and p != l), default=0)
        print('%2d %-26s %4d cases, %4d identical, %4d differ, largest relative difference %.1e'
              % (n, NAMES[n], len(res), exact, len(bad), worst), flush=True)
        for c, p, l in bad[:4]:
            print('    %s  pov %s  lucent %s' % (' '.join(text(a) for a in c[1]), show(p), show(l)))
finally:
    for f in os.listdir(work):
        os.unlink(os.path.join(work, f))
    os.rmdir(work)
EOF
)
exec python3 -c "$prog" "$@"

#!/bin/sh
# tests/bench/accuracy/selftest.sh: the error figures of `make accuracy`
# (acc_error in lib.sh) are right on images whose error is known: an image
# against itself gives 0, a copy with one pixel raised by 0.2 in every
# channel gives RMS sqrt(3 * 0.2^2 / (16 * 3)) = 0.05 and max 0.2, and one
# channel of one pixel lowered by 0.3 gives RMS sqrt(0.09 / 48); and the
# time comparison (acc_compare) gives the figures worked by hand below.
: "${top_srcdir:=$(cd "$(dirname "$0")/../../.." && pwd)}"
. "$top_srcdir/tests/bench/accuracy/lib.sh"
command -v oiiotool > /dev/null 2>&1 || { echo "selftest: oiiotool is needed" >&2; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/lucent-accself.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
fail=0

# check NAME GOT WANT_RMS WANT_MAX: GOT is "RMS MAX"; each within 1e-6.
check() {
	if echo "$2" | awk -v r="$3" -v m="$4" '
		function abs(x) { return x < 0 ? -x : x }
		NF == 2 && abs($1 - r) < 1e-6 && abs($2 - m) < 1e-6 { ok = 1 } END { exit !ok }'; then
		echo "ok: $1 ($2)"
	else
		echo "FAIL: $1: got '$2', want '$3 $4'"
		fail=1
	fi
}

oiiotool --pattern constant:color=0.5,0.5,0.5 4x4 3 -d float -o "$tmp/a.exr" || exit 1
oiiotool "$tmp/a.exr" --fill:color=0.7,0.7,0.7 1x1+2+1 -o "$tmp/b.exr" || exit 1
oiiotool "$tmp/a.exr" --fill:color=0.2,0.5,0.5 1x1+0+3 -o "$tmp/c.exr" || exit 1
check "image against itself" "$(acc_error "$tmp/a.exr" "$tmp/a.exr")" 0 0
check "one pixel +0.2" "$(acc_error "$tmp/a.exr" "$tmp/b.exr")" 0.05 0.2
check "one channel -0.3" "$(acc_error "$tmp/a.exr" "$tmp/c.exr")" "$(awk 'BEGIN { print sqrt(0.09 / 48) }')" 0.3
check "order does not matter" "$(acc_error "$tmp/b.exr" "$tmp/a.exr")" 0.05 0.2
if acc_error "$tmp/a.exr" "$tmp/missing.exr" > /dev/null; then
	echo "FAIL: a missing image gives figures"; fail=1
else
	echo "ok: a missing image fails"
fi
# acc_compare on two made-up curves (times and errors chosen so the figures
# can be worked by hand): lucent reaches 0.1 in 1 s and 0.01 in 4 s; POV-Ray
# 0.12 in 1 s, 0.05 in 2 s and 0.011 in 8 s (and 0.2 in 3 s, a setting slower
# and worse than another, which is off its curve).
pts='l 4 0.01
l 1 0.1
p 1 0.12
p 3 0.2
p 2 0.05
p 8 0.011'
# By settings, the ratios at the levels both reach (0.2 0.12 0.1 0.05
# 0.011): 1/1, 1/1, 2/1, 2/4, 8/4; 0.01 only lucent reaches.
got=$(echo "$pts" | acc_compare step)
want="1.00 0.50 2.00 5 1 0"
if [ "$got" = "$want" ]; then echo "ok: by settings ($got)"; else echo "FAIL: by settings: got '$got', want '$want'"; fail=1; fi
# On the curves: at 0.1 POV-Ray's time is 2^(ln(0.12/0.1)/ln(0.12/0.05)) =
# 1.155, at 0.05 lucent's 4^(ln 2/ln 10) = 1.518, at 0.011
# 4^(ln(0.1/0.011)/ln 10) = 3.776: ratios 1 1 1.155 1.318 2.119 (the
# lowest now 1: lucent's curve is nowhere above POV-Ray's).
got=$(echo "$pts" | acc_compare line)
want="1.16 1.00 2.12 5 1 0"
if [ "$got" = "$want" ]; then echo "ok: on the curves ($got)"; else echo "FAIL: on the curves: got '$got', want '$want'"; fail=1; fi
exit $fail

#!/bin/sh
# tests/bench/accuracy/selftest.sh: the error figures of `make accuracy`
# (acc_error in lib.sh) are right on images whose error is known: an image
# against itself gives 0, a copy with one pixel raised by 0.2 in every
# channel gives RMS sqrt(3 * 0.2^2 / (16 * 3)) = 0.05 and max 0.2, and one
# channel of one pixel lowered by 0.3 gives RMS sqrt(0.09 / 48).
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
exit $fail

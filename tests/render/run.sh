#!/bin/sh
# tests/render/run.sh: make check's render regression test. It runs
# lucent-regress (tools/lucent-regress.sh, doc/regress.md) on the corpus:
# every scene of tests/render/*.list (scenes/NAME.pov) is rendered with
# lucent and compared
#  (a) with tests/render/expected/NAME.png, exactly: rendering is
#      deterministic, so any changed pixel is a regression (or a deliberate
#      change: then run tests/render/refresh.sh and commit the new images);
#  (b) with POV-Ray 3.7's render tests/render/povray/NAME.png within the
#      scene's limits (default: no channel of any pixel off by more than
#      1/255).
# Each line of a list is "NAME WIDTH HEIGHT [LIMITS] [| SWITCHES]": the
# limits are idiff's options (e.g. -failpercent 0.02 -hardfail 0.05) for
# (b), and after "expected:" for (a); the switches (e.g. +A0.1 +AM2) go to
# both lucent and POV-Ray.
# Prints one line per scene, worst first, and ends with "N passed, M
# failed"; writes the HTML report to regress-report/ in the folder it was
# started from (the build folder under make check). Exit status 77 (skip)
# if OpenImageIO's oiiotool is missing.
# Environment: LUCENT, LUCENT_STDLIB, top_srcdir (make check sets them);
# REGRESS_JOBS (renders at once, default the number of cores),
# REGRESS_REPORT (the report folder).
: "${top_srcdir:=$(cd "$(dirname "$0")/../.." && pwd)}"
: "${LUCENT:=$PWD/lucent}"
export LUCENT
export LUCENT_STDLIB="${LUCENT_STDLIB:-$top_srcdir/stdlib}"

if ! command -v "${OIIOTOOL:-oiiotool}" > /dev/null 2>&1; then
	echo "SKIP: oiiotool (OpenImageIO) not found"
	exit 77
fi
report=${REGRESS_REPORT:-$PWD/regress-report}
cd "$top_srcdir" || exit 1
exec sh tools/lucent-regress.sh ${REGRESS_JOBS:+-j "$REGRESS_JOBS"} \
	-o "$report" --scenes scenes tests/render

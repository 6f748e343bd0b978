#!/bin/sh
# tests/render/refresh.sh: regenerate the reference images of the render
# tests, for every scene in tests/render/*.list (or only the scenes
# named on the command line; shell patterns such as 'light-*' work too):
#   tests/render/povray/NAME.png    POV-Ray 3.7's render of scenes/NAME.pov
#   tests/render/povray/NAME.time   POV-Ray's CPU and wall-clock time for it
#   tests/render/expected/NAME.png  lucent's render, which run.sh must then
#                                   reproduce exactly
# It runs lucent-regress --refresh (tools/lucent-regress.sh), several
# renders at once. It works from any folder (make refresh-references runs
# it). Run it after any deliberate change to rendering, then look at the
# new images and at run.sh's figures against POV-Ray before committing them.
#
# Usage: refresh.sh [--lucent | --povray | --times] [NAME]...
#   --lucent  only lucent's expected images (POV-Ray's are left as they are)
#   --povray  only POV-Ray's images and times
#   --times   only POV-Ray's times (its images are left as they are)
# Environment: LUCENT (default ./lucent), POVRAY (default povray),
# LUCENT_STDLIB (default the source tree's stdlib/), REGRESS_JOBS (renders
# at once, default the number of cores).
top=$(cd "$(dirname "$0")/../.." && pwd) || exit 1
LUCENT=${LUCENT:-./lucent}
# A path relative to where we were started, made absolute before the cd.
case $LUCENT in
/*) ;;
*/*) LUCENT=$PWD/$LUCENT ;;
esac
export LUCENT
export LUCENT_STDLIB="${LUCENT_STDLIB:-$top/stdlib}"
what=all
case $1 in
--lucent | --povray | --times) what=${1#--}; shift ;;
esac
cd "$top" || exit 1

# Each NAME becomes "-n NAME".
n=$#
while [ "$n" -gt 0 ]; do
	set -- "$@" -n "$1"
	shift
	n=$((n - 1))
done
exec sh tools/lucent-regress.sh --refresh="$what" ${REGRESS_JOBS:+-j "$REGRESS_JOBS"} \
	--scenes scenes "$@" tests/render

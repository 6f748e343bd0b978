#!/bin/sh
# doc/images/cameras/render.sh: render the pictures of the Cameras part of
# doc/lights-cameras.md from the corpus scenes: scenes/cam-NAME.pov
# becomes NAME.png here, at 160x120. Run it from anywhere; it uses the
# lucent binary at the top of the source tree unless LUCENT names another.
#   doc/images/cameras/render.sh                 every scenes/cam-*.pov
#   doc/images/cameras/render.sh fisheye bokeh   only these
here=$(cd "$(dirname "$0")" && pwd) || exit 1
top=$(cd "$here/../../.." && pwd) || exit 1
LUCENT=${LUCENT:-$top/lucent}
# A path relative to where we were started, made absolute before the cd.
case $LUCENT in
/*) ;;
*/*) LUCENT=$PWD/$LUCENT ;;
esac
LUCENT_STDLIB=${LUCENT_STDLIB:-$top/stdlib}
export LUCENT_STDLIB
cd "$here" || exit 1

if [ $# -eq 0 ]; then
	for f in "$top"/scenes/cam-*.pov; do
		f=${f##*/cam-}
		set -- "$@" "${f%.pov}"
	done
fi
status=0
for name in "$@"; do
	if ! "$LUCENT" -q +W160 +H120 "$top/scenes/cam-$name.pov" +O"$name.png" < /dev/null; then
		echo "$name: lucent failed" >&2
		status=1
	fi
done
exit $status

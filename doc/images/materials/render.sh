#!/bin/sh
# doc/images/materials/render.sh: render the pictures of doc/materials.md.
# Every NAME.pov in this folder becomes NAME.png at 240x180. Run it from
# anywhere; it uses the lucent binary at the top of the source tree
# unless LUCENT names another.
#   doc/images/materials/render.sh              every scene
#   doc/images/materials/render.sh finish glass only these
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
# The image module, for image_map.pov.
if [ -z "$LUCENT_OIIO_MODULE" ] && [ -f "$top/lucent-oiio.so" ]; then
	LUCENT_OIIO_MODULE=$top/lucent-oiio.so
	export LUCENT_OIIO_MODULE
fi
cd "$here" || exit 1

if [ $# -eq 0 ]; then
	for f in *.pov; do
		set -- "$@" "${f%.pov}"
	done
fi
status=0
for name in "$@"; do
	if ! "$LUCENT" -q +W240 +H180 "$name.pov" +O"$name.png" < /dev/null; then
		echo "$name: lucent failed" >&2
		status=1
	fi
done
exit $status

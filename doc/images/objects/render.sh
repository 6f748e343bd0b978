#!/bin/sh
# doc/images/objects/render.sh: render the pictures of doc/objects.md.
# Every NAME.pov in this folder becomes NAME.png at 240x180, and
# difference.pov is rendered once more with --signature as
# difference-signature.png. Run it from anywhere; it uses the lucent
# binary at the top of the source tree unless LUCENT names another.
#   doc/images/objects/render.sh            every scene
#   doc/images/objects/render.sh torus box  only these
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
	if [ "$name" = difference ] &&
	   ! "$LUCENT" -q --signature +W240 +H180 difference.pov +Odifference-signature.png < /dev/null; then
		echo "difference (--signature): lucent failed" >&2
		status=1
	fi
done
exit $status

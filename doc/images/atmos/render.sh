#!/bin/sh
# doc/images/atmos/render.sh: render the pictures of the Atmosphere part of
# doc/rendering.md (one 120x90 swatch per scene of tests/render/atmos.list;
# the +UA scenes are shown over a grey checker so that their alpha shows)
# with the lucent binary at the top of the source tree unless LUCENT names
# another. Needs oiiotool (OpenImageIO) for the checker.
here=$(cd "$(dirname "$0")" && pwd) || exit 1
top=$(cd "$here/../../.." && pwd) || exit 1
LUCENT=${LUCENT:-$top/lucent}
case $LUCENT in
/*) ;;
*/*) LUCENT=$PWD/$LUCENT ;;
esac
LUCENT_STDLIB=${LUCENT_STDLIB:-$top/stdlib}
export LUCENT_STDLIB
tmp=$(mktemp -d "${TMPDIR:-/tmp}/lucent-docimg.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
cd "$top" || exit 1
set -e
grep -v '^#' tests/render/atmos.list | while read -r name rest; do
	case $rest in
	*+UA*)
		"$LUCENT" -q +W120 +H90 +A0.2 -J +UA +Lscenes "scenes/$name.pov" +O"$tmp/$name.png"
		oiiotool --pattern checker:width=10:height=10:color1=0.8,0.8,0.8,1:color2=0.55,0.55,0.55,1 120x90 4 \
			-o "$tmp/checker.png"
		oiiotool "$tmp/$name.png" "$tmp/checker.png" --over --ch R,G,B -o "$here/$name.png"
		;;
	*) "$LUCENT" -q +W120 +H90 +A0.2 -J +Lscenes "scenes/$name.pov" +O"$here/$name.png" ;;
	esac
done

#!/bin/sh
# doc/images/lights/render.sh: render the pictures of the Lights part of
# doc/lights-cameras.md (one 120x90 swatch per light scene of
# tests/render/lights.list) with the lucent binary at the top of the source
# tree unless LUCENT names another.
here=$(cd "$(dirname "$0")" && pwd) || exit 1
top=$(cd "$here/../../.." && pwd) || exit 1
LUCENT=${LUCENT:-$top/lucent}
case $LUCENT in
/*) ;;
*/*) LUCENT=$PWD/$LUCENT ;;
esac
LUCENT_STDLIB=${LUCENT_STDLIB:-$top/stdlib}
export LUCENT_STDLIB
cd "$top" || exit 1
set -e
for name in $(grep -v '^#' tests/render/lights.list | awk '{print $1}'); do
	"$LUCENT" -q +W120 +H90 +A0.2 -J +Lscenes "scenes/$name.pov" +O"$here/$name.png"
done

#!/bin/sh
# doc/images/rendering/render.sh: render the pictures of doc/rendering.md
# (antialiasing and quality levels) from the test scenes in scenes/, with
# the lucent binary at the top of the source tree unless LUCENT names
# another. Needs oiiotool (OpenImageIO) to crop, enlarge and tile.
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
# Antialiasing: the checker scene without, with method 1 and with method
# 2 (no jitter), and method 1 with jitter; an 80x60 part enlarged 3x.
i=0
for sw in "-A" "+A0.1 -J +AM1 +R3" "+A0.1 -J +AM2 +R3" "+A0.1 +J +AM1 +R3"; do
	# shellcheck disable=SC2086 # the switches are meant to be split
	"$LUCENT" -q +W320 +H240 $sw scenes/aa-checker.pov +O"$tmp/aa$i.png"
	oiiotool "$tmp/aa$i.png" --cut 80x60+40+95 --resize:filter=box 240x180 -o "$tmp/aa${i}c.png"
	i=$((i + 1))
done
oiiotool "$tmp/aa0c.png" "$tmp/aa1c.png" "$tmp/aa2c.png" "$tmp/aa3c.png" --mosaic:pad=4 4x1 -o "$here/antialias.png"
# Quality levels 0, 2, 4, 6 and 8 (1, 3, 5, 7 and 9 look like the level below).
for q in 0 2 4 6 8; do
	"$LUCENT" -q +W160 +H120 +Q$q +Lscenes scenes/quality-q$q.pov +O"$tmp/q$q.png"
done
oiiotool "$tmp/q0.png" "$tmp/q2.png" "$tmp/q4.png" "$tmp/q6.png" "$tmp/q8.png" --mosaic:pad=4 5x1 -o "$here/quality.png"

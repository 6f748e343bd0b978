#!/bin/sh
# tests/includes.sh: lucent parses every include file POV-Ray 3.7 ships
# (/usr/share/povray-3.7/include/*.inc, or $POV_INCLUDE), each in a scene
#   #version 3.7; #include "colors.inc" #include "shapes.inc" #include "X.inc"
# with the folder on the library path. A file passes when lucent exits with
# status 0 (an empty scene renders, so nothing else can fail).
#
# Files that need something not written yet are listed in
# tests/includes-pending.list ("name.inc  reason"); they are reported as
# SKIP while they fail and fail the run once they pass, so the list stays
# honest. Without POV-Ray's include folder the test is skipped (77).
. "${top_srcdir:-.}/tests/lib.sh"
inc=${POV_INCLUDE:-/usr/share/povray-3.7/include}
if [ ! -f "$inc/colors.inc" ]; then
	echo "SKIP: no POV-Ray include folder at $inc"
	exit 77
fi
list="$top_srcdir/tests/includes-pending.list"
pending() { grep -q "^$1[[:space:]]" "$list" 2>/dev/null; }
cd "$WORK" || exit 1
for path in "$inc"/*.inc; do
	name=$(basename "$path")
	printf '#version 3.7;\n#include "colors.inc"\n#include "shapes.inc"\n#include "%s"\n' "$name" > scene.pov
	"$LUCENT" -q +W8 +H6 +L"$inc" scene.pov +O"$WORK/out.png" > err.txt 2>&1
	rc=$?
	if [ $rc -eq 0 ]; then
		if pending "$name"; then
			fail "$name parses now: remove it from tests/includes-pending.list"
		else
			pass "$name"
		fi
	elif pending "$name"; then
		echo "SKIP: $name ($(head -n 1 err.txt))"
	else
		fail "$name: exit status $rc"
		sed 's/^/    | /' err.txt | head -n 5
	fi
done
finish

#!/bin/sh
# tests/stdlib.sh: every file of lucent's stdlib/ parses on its own (it
# includes what it needs) and all of them together, with no warning or
# error: for each stdlib/NAME.inc a scene "#version 3.7; #include NAME.inc"
# must render with exit status 0 and print nothing on stderr; then one scene
# including every file.
. "${top_srcdir:-.}/tests/lib.sh"
lib="$top_srcdir/stdlib"
cd "$WORK" || exit 1
all=""
for path in "$lib"/*.inc; do
	name=$(basename "$path")
	all="$all#include \"$name\"
"
	printf '#version 3.7;\n#include "%s"\n' "$name" > scene.pov
	"$LUCENT" -q +W8 +H6 scene.pov +O"$WORK/out.png" < /dev/null > err.txt 2>&1
	rc=$?
	if [ $rc -eq 0 ] && [ ! -s err.txt ]; then
		pass "$name alone"
	else
		fail "$name alone: exit status $rc"
		sed 's/^/    | /' err.txt | head -n 5
	fi
done
printf '#version 3.7;\n%s' "$all" > scene.pov
"$LUCENT" -q +W8 +H6 scene.pov +O"$WORK/out.png" < /dev/null > err.txt 2>&1
rc=$?
if [ $rc -eq 0 ] && [ ! -s err.txt ]; then
	pass "all files together"
else
	fail "all files together: exit status $rc"
	sed 's/^/    | /' err.txt | head -n 5
fi
finish

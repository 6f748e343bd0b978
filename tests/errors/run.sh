#!/bin/sh
# tests/errors/run.sh: every broken scene in tests/errors/*.pov must make
# lucent exit with status 1, write no image, and print
#   FILE:LINE:COL: error: MESSAGE
# followed by the quoted source line and a caret. Each scene states what is
# expected in its first lines:
#   // expect: LINE:COL: MESSAGE      (FILE is the scene itself)
#   // expect-file: NAME              (the error is in NAME, e.g. an include)
#   // expect-also: TEXT              (more text that must appear; repeatable)
. "${top_srcdir:-.}/tests/lib.sh"
dir="$top_srcdir/tests/errors"
cd "$dir" || exit 1
for scene in *.pov; do
	[ -f "$scene" ] || continue
	expect=$(sed -n 's|^// expect: ||p' "$scene" | head -n 1)
	if [ -z "$expect" ]; then
		fail "$scene: no '// expect:' line"
		continue
	fi
	file=$(sed -n 's|^// expect-file: ||p' "$scene" | head -n 1)
	[ -n "$file" ] || file=$scene
	loc=${expect%%: *}
	msg=${expect#*: }
	out="$WORK/${scene%.pov}.png"
	# +L: the image tests read tests/data (outside this folder) under the
	# file rule.
	"$LUCENT" -q +W8 +H6 +L"$top_srcdir/tests/data" "$scene" +O"$out" > "$WORK/err.txt" 2>&1
	rc=$?
	ok=1
	why=""
	if [ $rc -ne 1 ]; then ok=0; why="exit status $rc, not 1"; fi
	if ! grep -qF -- "$file:$loc: error: $msg" "$WORK/err.txt"; then
		ok=0; why="$why; no '$file:$loc: error: $msg'"
	fi
	# The quoted line and the caret under the column.
	if ! grep -qE '^ +[0-9]+ \| ' "$WORK/err.txt" || ! grep -qE '^ +\| *	*\^$' "$WORK/err.txt"; then
		ok=0; why="$why; no quoted line with a caret"
	fi
	sed -n 's|^// expect-also: ||p' "$scene" > "$WORK/also.txt"
	while IFS= read -r also; do
		if ! grep -qF -- "$also" "$WORK/err.txt"; then ok=0; why="$why; missing '$also'"; fi
	done < "$WORK/also.txt"
	if [ -f "$out" ]; then ok=0; why="$why; an image was written"; fi
	if [ $ok -eq 1 ]; then
		pass "$scene"
	else
		fail "$scene:$why"
		sed 's/^/    | /' "$WORK/err.txt"
	fi
done
finish

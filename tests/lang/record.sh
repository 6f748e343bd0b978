#!/bin/sh
# tests/lang/record.sh: record the expected #debug output of the language
# test programs by running POV-Ray 3.7 on them.
#
#   tests/lang/record.sh                 record every tests/lang/*.pov
#   tests/lang/record.sh expr-add.pov …  record only these (names or paths)
#
# Each program runs in a fresh copy of tests/lang (so files it writes with
# #fopen/#write never land in the source tree and never leak from one run
# into the next), with that copy as the current directory, as
#   povray -D -F +W8 +H8 +GD<name>.dbg +I<name>.pov
# and its #debug stream is stored as tests/lang/<name>.expected.
#
# POV-Ray's default I/O restrictions (povray.conf) allow reading and
# writing under /tmp and in the current folder, which is why the copy is
# made under ${TMPDIR:-/tmp}.
#
# The script fails loudly, and stores nothing for that program, if POV-Ray
# exits with an error or reports a parse error: everything in this corpus
# must be valid POV-Ray 3.7.
POVRAY=${POVRAY:-povray}
here=$(cd "$(dirname "$0")" && pwd) || exit 1
command -v "$POVRAY" > /dev/null 2>&1 || { echo "record.sh: $POVRAY not found" >&2; exit 1; }

work=$(mktemp -d "${TMPDIR:-/tmp}/lucent-lang-record.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT INT TERM

if [ $# -eq 0 ]; then
	set -- "$here"/*.pov
fi

nok=0
nbad=0
for prog in "$@"; do
	name=$(basename "$prog" .pov)
	if [ ! -f "$here/$name.pov" ]; then
		echo "record.sh: no such program: $here/$name.pov" >&2
		nbad=$((nbad + 1))
		continue
	fi
	# A fresh copy of the folder for every program.
	rm -rf "$work/run"
	mkdir "$work/run" || exit 1
	(cd "$here" && tar cf - --exclude='*.expected' --exclude='*.out' .) | (cd "$work/run" && tar xf -) || exit 1
	(cd "$work/run" && "$POVRAY" -D -F +W8 +H8 +GD"$name.dbg" +I"$name.pov" > "$work/log.txt" 2>&1)
	rc=$?
	# "Possible Parse Error" is POV-Ray's wording for some warnings
	# (e.g. assumed_gamma); real parse errors read "File ... Parse Error:".
	if [ $rc -ne 0 ] || grep -a -E 'Parse Error:|Fatal error' "$work/log.txt" | grep -a -q -v 'Possible Parse Error'; then
		echo "ERROR: $name.pov: POV-Ray failed (exit status $rc)" >&2
		grep -a -A3 -E 'Parse Error:|Fatal error|rror' "$work/log.txt" | grep -av 'Possible Parse Error' >&2
		nbad=$((nbad + 1))
		continue
	fi
	if [ ! -f "$work/run/$name.dbg" ]; then
		# No #debug output at all: record an empty file.
		: > "$work/run/$name.dbg"
	fi
	cp "$work/run/$name.dbg" "$here/$name.expected" || exit 1
	nok=$((nok + 1))
done
echo "record.sh: $nok recorded, $nbad failed"
[ "$nbad" -eq 0 ]

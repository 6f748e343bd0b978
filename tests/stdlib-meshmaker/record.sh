#!/bin/sh
# tests/stdlib-meshmaker/record.sh: record what POV-Ray 3.7 writes for
# write.pov (its files and the #debug stream of two runs), the expected
# output of the meshmaker part of tests/stdlib.sh.
POVRAY=${POVRAY:-povray}
here=$(cd "$(dirname "$0")" && pwd) || exit 1
work=$(mktemp -d "${TMPDIR:-/tmp}/lucent-mm-record.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT INT TERM
cp "$here/write.pov" "$work/" || exit 1
cd "$work" || exit 1
for run in 1 2; do
	"$POVRAY" -D -F +W8 +H8 +GDrun$run.dbg +Iwrite.pov > log.txt 2>&1 || { cat log.txt; exit 1; }
done
rm -f "$here"/expected/*
mkdir -p "$here/expected"
for f in *; do
	case $f in write.pov|log.txt) ;; *) cp "$f" "$here/expected/$f" ;; esac
done
ls "$here/expected"

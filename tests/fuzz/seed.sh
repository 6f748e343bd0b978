#!/bin/sh
# tests/fuzz/seed.sh: the seed corpus: every scene and test program in the
# repository (scenes/, tests/**/*.pov, the stdlib's include files), copied
# flat into OUTDIR under names that keep their origin.
#   seed.sh TOP_SRCDIR OUTDIR
set -e
top=${1:-.}
out=${2:-corpus}
mkdir -p "$out"
cd "$top"
find scenes tests stdlib -type f \( -name '*.pov' -o -name '*.inc' \) | sort | while read -r f; do
	cp "$f" "$out/$(echo "$f" | tr '/' '_')"
done
echo "seed.sh: $(ls "$out" | wc -l) files in $out" >&2

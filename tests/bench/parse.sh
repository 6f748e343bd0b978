#!/bin/sh
# tests/bench/parse.sh: parse time of lucent and POV-Ray on the parse
# benchmarks, measured in the same run, and their ratio. Each program
# reports its own parse time (lucent's statistics, POV-Ray's "Parse Time").
# Run by `make bench`; never by `make check` (it asserts nothing).
: "${top_srcdir:=$(cd "$(dirname "$0")/../.." && pwd)}"
: "${LUCENT:=$top_srcdir/lucent}"
cd "$top_srcdir/tests/bench" || exit 1
printf '%-16s %12s %12s %8s\n' scene lucent povray ratio
for scene in parse-while parse-macro bench-spheres; do
	l=$("$LUCENT" -F +W1 +H1 +WT1 "$scene.pov" 2>&1 | sed -n 's/^  parse *\([0-9.]*\) s$/\1/p')
	if command -v povray > /dev/null 2>&1; then
		p=$(povray -D -F +W1 +H1 +WT1 "+I$scene.pov" 2>&1 | sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p')
	else
		p=""
	fi
	if [ -n "$p" ] && [ -n "$l" ]; then
		r=$(awk -v a="$p" -v b="$l" 'BEGIN { if (b > 0) printf "%.1fx", a / b; else print "-" }')
	else
		r="-"
	fi
	printf '%-16s %11ss %11ss %8s\n' "$scene" "$l" "${p:--}" "$r"
done

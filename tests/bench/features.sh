#!/bin/sh
# tests/bench/features.sh: what an effect costs, and that an effect a scene
# does not use costs nothing. lucent decides before rendering which effects
# a scene can show (doc/rendering.md, "Simulate only what the scene calls
# for") and the tracer never tests for the others, so:
#   matte          the matte scene (no reflection anywhere)
#   matte +Q7      the same with reflection switched off by the quality
#                  level: the tracer as if built without reflection
#   one mirror     the same scene with one reflective sphere
#   matte +A0.3    antialiasing method 1
#   matte +AM2     antialiasing method 2
# For each: render time (best of RUNS, one thread so that the figures do not
# depend on the machine's load balance), camera samples per pixel and rays
# by kind from lucent's statistics. "matte" and "matte +Q7" should be equal
# within noise. Asserts nothing; run by `make bench`.
: "${top_srcdir:=$(cd "$(dirname "$0")/../.." && pwd)}"
: "${LUCENT:=$top_srcdir/lucent}"
W=${BENCH_W:-480}
H=${BENCH_H:-360}
RUNS=${BENCH_RUNS:-3}
cd "$top_srcdir/tests/bench" || exit 1
out=$(mktemp -d "${TMPDIR:-/tmp}/lucent-bench.XXXXXX") || exit 1
trap 'rm -rf "$out"' EXIT

# stat NAME FILE: the number on lucent's statistics line NAME.
stat() { sed -n "s/^ *$1 *\([0-9.]*\).*/\1/p" "$2" | head -1; }

printf 'image %dx%d, 1 render thread, best of %d runs\n' "$W" "$H" "$RUNS"
printf '%-14s %9s %9s %11s %11s %11s  %s\n' case render_s samples/px camera shadow reflected simulated
run() {
	label=$1
	shift
	best=""
	i=0
	while [ $i -lt "$RUNS" ]; do
		"$LUCENT" +WT1 +W"$W" +H"$H" -F bench-features.pov "$@" > "$out/log" 2>&1 || {
			echo "$label: lucent failed" >&2
			return
		}
		t=$(stat render "$out/log")
		best=$(awk -v a="$best" -v b="$t" 'BEGIN { print (a == "" || b < a) ? b : a }')
		i=$((i + 1))
	done
	spp=$(sed -n 's/^  samples .*(\([0-9.]*\) per pixel).*/\1/p' "$out/log")
	sim=$(sed -n 's/^  simulated *//p' "$out/log")
	printf '%-14s %9s %9s %11s %11s %11s  %s\n' "$label" "$best" "$spp" "$(stat camera "$out/log")" \
		"$(stat shadow "$out/log")" "$(stat reflected "$out/log")" "$sim"
}
run "matte"
run "matte +Q7" +Q7
run "one mirror" Declare=MIRROR=1
run "matte +A0.3" +A0.3
run "matte +AM2" +A0.3 +AM2

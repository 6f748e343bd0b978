#!/bin/sh
# tests/bench/render.sh: lucent and POV-Ray 3.7 on the geometry benchmarks,
# measured in the same run with the same switches (both using every core):
#   bench-spheres  100,000 spheres placed by a macro in a loop with rand
#   bench-mesh2    a million-triangle, ~38 MB mesh2 (written here by
#                  gen-mesh2.sh into mesh1m.inc when missing)
# For each program: parse time, the time to build its hierarchies
# (lucent's prepare plus, for meshes, the build inside parse as reported
# below; POV-Ray's Bounding Time), render time (POV-Ray's Trace Time),
# peak memory (GNU time's maximum resident set) and camera rays per second
# of render time. Ratios are POV-Ray's over lucent's. Asserts nothing; run
# by `make bench`. BENCH_SCENES (names without .pov) picks the scenes, e.g.
#   BENCH_SCENES=bench-mesh2 sh tests/bench/render.sh
: "${top_srcdir:=$(cd "$(dirname "$0")/../.." && pwd)}"
: "${LUCENT:=$top_srcdir/lucent}"
W=${BENCH_W:-800}
H=${BENCH_H:-600}
cd "$top_srcdir/tests/bench" || exit 1
[ -f mesh1m.inc ] || sh ./gen-mesh2.sh 707 mesh1m.inc
TIME=/usr/bin/time
[ -x "$TIME" ] || { echo "render.sh: GNU time ($TIME) is needed for peak memory" >&2; exit 1; }
out=$(mktemp -d "${TMPDIR:-/tmp}/lucent-bench.XXXXXX") || exit 1
trap 'rm -rf "$out"' EXIT

# field NAME FILE: the seconds on lucent's statistics line NAME.
field() { sed -n "s/^  $1 *\([0-9.]*\) s\$/\1/p" "$2"; }
# povfield LABEL FILE: the seconds in POV-Ray's "LABEL Time: ... (N seconds)".
povfield() { sed -n "s/.*$1 Time:.*(\([0-9.]*\) seconds).*/\1/p" "$2" | head -1; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a != "" && b > 0) printf "%.2fx", a / b; else print "-" }'; }
mrays() { awk -v n="$1" -v t="$2" 'BEGIN { if (t > 0) printf "%.2f", n / t / 1e6; else print "-" }'; }

printf 'image %dx%d, %s render threads\n' "$W" "$H" "all"
printf '%-14s %-8s %9s %9s %9s %9s %10s\n' scene program parse build render peak_MB "Mrays/s"
for scene in ${BENCH_SCENES:-bench-spheres bench-mesh2}; do
	"$TIME" -f 'peak %M' "$LUCENT" +W"$W" +H"$H" "$scene.pov" +O"$out/$scene-lucent.png" \
		> "$out/l.log" 2>&1
	lp=$(field parse "$out/l.log"); lb=$(field prepare "$out/l.log"); lr=$(field render "$out/l.log")
	lm=$(sed -n 's/^peak \([0-9]*\)$/\1/p' "$out/l.log")
	printf '%-14s %-8s %9s %9s %9s %9s %10s\n' "$scene" lucent "$lp" "$lb" "$lr" \
		"$((lm / 1024))" "$(mrays $((W * H)) "$lr")"
	if command -v povray > /dev/null 2>&1; then
		"$TIME" -f 'peak %M' povray -D +W"$W" +H"$H" "+I$scene.pov" +O"$out/$scene-povray.png" \
			> "$out/p.log" 2>&1
		pp=$(povfield Parse "$out/p.log"); pb=$(povfield Bounding "$out/p.log"); pr=$(povfield Trace "$out/p.log")
		pm=$(sed -n 's/^peak \([0-9]*\)$/\1/p' "$out/p.log")
		printf '%-14s %-8s %9s %9s %9s %9s %10s\n' "" povray "$pp" "$pb" "$pr" "$((pm / 1024))" \
			"$(mrays $((W * H)) "$pr")"
		lrb=$(awk -v a="$lb" -v b="$lr" 'BEGIN { print a + b }')
		prb=$(awk -v a="$pb" -v b="$pr" 'BEGIN { print a + b }')
		printf '%-14s %-8s %9s %9s %9s %9s\n' "" ratio "$(ratio "$pp" "$lp")" "$(ratio "$pb" "$lb")" \
			"$(ratio "$pr" "$lr")" "$(ratio "$pm" "$lm")"
		printf '%-14s render time with hierarchy building: lucent %.3f s, POV-Ray %.3f s (%s)\n' "" \
			"$lrb" "$prb" "$(ratio "$prb" "$lrb")"
	fi
done

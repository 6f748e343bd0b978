#!/bin/sh
# tests/bench/corpus.sh: lucent and POV-Ray 3.7 on every corpus scene and
# on the benchmark scenes, measured in the same run with the same switches,
# both using every core (issue 7, "Performance figures").
#
# The corpus is what tests/render/*.list name (scenes/NAME.pov at the
# list's size, with the list's "| SWITCHES"); the benchmark scenes are
# tests/bench/bench-*.pov at BENCH_W x BENCH_H (default 800x600). For each
# scene and program: parse time (each program's own figure: lucent's
# statistics line `parse`, POV-Ray's "Parse Time"), render time (lucent's
# `prepare` + `render`; POV-Ray's Bounding, Photon, Radiosity and Trace
# times), total wall time and user+system CPU time of the whole run and
# peak resident memory (GNU time), and the ratios POV-Ray / lucent. At the
# end: the median ratios over the corpus. Writing the image is part of the
# total (PNG). Asserts nothing; run by `make bench`.
#
# Environment:
#   CORPUS_SCENES="NAME..."  only these scenes (shell patterns; the
#                            benchmark scenes are bench-spheres,
#                            bench-mesh2, bench-features)
#   CORPUS_BENCH=no          leave out the benchmark scenes
#   CORPUS_OUT=FILE          also write the table (tab-separated) to FILE
#   BENCH_W, BENCH_H         the benchmark scenes' size
#   LUCENT, POVRAY           the programs (default: the build's lucent, povray)
: "${top_srcdir:=$(cd "$(dirname "$0")/../.." && pwd)}"
: "${LUCENT:=$top_srcdir/lucent}"
: "${POVRAY:=povray}"
BW=${BENCH_W:-800}
BH=${BENCH_H:-600}
TIME=/usr/bin/time
[ -x "$TIME" ] || { echo "corpus.sh: GNU time ($TIME) is needed" >&2; exit 1; }
command -v "$POVRAY" > /dev/null 2>&1 || { echo "corpus.sh: povray not found ($POVRAY)" >&2; exit 1; }
command -v python3 > /dev/null 2>&1 || { echo "corpus.sh: python3 is needed (timing)" >&2; exit 1; }
LUCENT_STDLIB=${LUCENT_STDLIB:-$top_srcdir/stdlib}
export LUCENT_STDLIB
out=$(mktemp -d "${TMPDIR:-/tmp}/lucent-corpus.XXXXXX") || exit 1
trap '[ -n "${CORPUS_KEEP:-}" ] || rm -rf "$out"' EXIT
lists=$(ls "$top_srcdir"/tests/render/*.list)
set -f

# wanted NAME: is NAME selected by CORPUS_SCENES?
wanted() {
	[ -z "${CORPUS_SCENES:-}" ] && return 0
	for pat in $CORPUS_SCENES; do
		# shellcheck disable=SC2254
		case $1 in $pat) return 0 ;; esac
	done
	return 1
}

# The scenes: "NAME<tab>W<tab>H<tab>PATH<tab>SWITCHES" lines.
for list in $lists; do
	sed -e 's/#.*//' "$list" | while IFS= read -r line; do
		sw=""
		case $line in *'|'*) sw=${line#*|}; line=${line%%|*} ;; esac
		# shellcheck disable=SC2086
		set -- $line
		[ $# -ge 3 ] || continue
		wanted "$1" || continue
		printf '%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$top_srcdir/scenes/$1.pov" "$(echo $sw)"
	done
done > "$out/scenes"
ncorpus=$(wc -l < "$out/scenes")
if [ "${CORPUS_BENCH:-yes}" != no ]; then
	for b in bench-spheres bench-mesh2 bench-features; do
		wanted "$b" || continue
		if [ "$b" = bench-mesh2 ] && [ ! -f "$top_srcdir/tests/bench/mesh1m.inc" ]; then
			(cd "$top_srcdir/tests/bench" && sh ./gen-mesh2.sh 707 mesh1m.inc) || continue
		fi
		printf '%s\t%s\t%s\t%s\t\n' "$b" "$BW" "$BH" "$top_srcdir/tests/bench/$b.pov"
	done >> "$out/scenes"
fi
[ -s "$out/scenes" ] || { echo "corpus.sh: no scene selected" >&2; exit 1; }

# measure CMD...: run CMD (output to stdout/stderr as it is) under GNU
# time for the peak memory, timing it here to the microsecond (GNU time's
# 10 ms steps round small scenes to 0): prints "gnutime WALL USER SYS KB"
# as the last line of stderr. USER and SYS come from getrusage of the
# children (the same accounting GNU time reads; GNU time's own is a
# fraction of a millisecond), counted from the start of the command.
measure() {
	python3 -c '
import resource, subprocess, sys, time
r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
t0 = time.perf_counter()
p = subprocess.run(["'"$TIME"'", "-f", "gnutime-peak %M"] + sys.argv[1:])
wall = time.perf_counter() - t0
r = resource.getrusage(resource.RUSAGE_CHILDREN)
sys.stderr.flush()
print("gnutime %.4f %.4f %.4f" % (wall, r.ru_utime - r0.ru_utime, r.ru_stime - r0.ru_stime), file=sys.stderr)
sys.exit(p.returncode)' "$@"
}

# field NAME FILE: the seconds on lucent's statistics line NAME.
field() { sed -n "s/^  $1 *\([0-9.]*\) s\$/\1/p" "$2" | head -1; }
# povfield LABEL FILE: the seconds in POV-Ray's "LABEL Time: ... (N seconds)".
povfield() { sed -n "s/.*$1 Time:.*(\([0-9.]*\) seconds).*/\1/p" "$2" | head -1; }
# gnu FILE: "wall cpu peak_MB" from measure's lines.
gnu() {
	peak=$(sed -n 's/^gnutime-peak \([0-9]*\)$/\1/p' "$1" | tail -1)
	sed -n 's/^gnutime \([0-9.]*\) \([0-9.]*\) \([0-9.]*\)$/\1 \2 \3/p' "$1" | tail -1 |
		awk -v m="${peak:-0}" '{ printf "%.3f %.3f %.1f", $1, $2 + $3, m / 1024 }'
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a != "" && b > 0) printf "%.2f", a / b; else print "-" }'; }
add() { awk 'BEGIN { s = 0; for (i = 1; i < ARGC; i++) s += ARGV[i]; printf "%.3f", s }' "$@"; }

fmt='%-22s %-7s %8s %8s %8s %8s %8s\n'
printf 'lucent and POV-Ray 3.7, same switches, every core (%s); times in seconds\n' "$(nproc) cores"
printf "$fmt" scene program parse render wall cpu peak_MB
printf 'scene\tw\th\tswitches\tl_parse\tl_render\tl_wall\tl_cpu\tl_peak_mb\tp_parse\tp_render\tp_wall\tp_cpu\tp_peak_mb\n' > "$out/table"
n=0
while IFS='	' read -r name w h scene sw; do
	n=$((n + 1))
	dir=$(dirname "$scene")
	# shellcheck disable=SC2086 # the switches are meant to be split
	(cd "$dir" && measure "$LUCENT" +W"$w" +H"$h" $sw "$scene" +O"$out/l.png") \
		> "$out/l.log" 2>&1 < /dev/null
	lp=$(field parse "$out/l.log")
	lr=$(add "$(field prepare "$out/l.log")" "$(field render "$out/l.log")")
	set -- $(gnu "$out/l.log")
	lw=${1:-} lc=${2:-} lm=${3:-}
	# shellcheck disable=SC2086
	(cd "$dir" && measure "$POVRAY" -D $sw +W"$w" +H"$h" +I"$scene" +O"$out/p.png") \
		> "$out/p.log" 2>&1 < /dev/null
	pp=$(povfield Parse "$out/p.log")
	pr=$(add "$(povfield Bounding "$out/p.log")" "$(povfield Photon "$out/p.log")" \
		"$(povfield Radiosity "$out/p.log")" "$(povfield Trace "$out/p.log")")
	set -- $(gnu "$out/p.log")
	pw=${1:-} pc=${2:-} pm=${3:-}
	printf "$fmt" "$name" lucent "$lp" "$lr" "$lw" "$lc" "$lm"
	printf "$fmt" "" povray "$pp" "$pr" "$pw" "$pc" "$pm"
	printf "$fmt" "" ratio "$(ratio "$pp" "$lp")" "$(ratio "$pr" "$lr")" "$(ratio "$pw" "$lw")" \
		"$(ratio "$pc" "$lc")" "$(ratio "$pm" "$lm")"
	printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$w" "$h" "$sw" \
		"$lp" "$lr" "$lw" "$lc" "$lm" "$pp" "$pr" "$pw" "$pc" "$pm" >> "$out/table"
	[ "$n" -eq "$ncorpus" ] && cp "$out/table" "$out/corpus-table"
done < "$out/scenes"
[ -n "${CORPUS_OUT:-}" ] && cp "$out/table" "$CORPUS_OUT"

# The medians over the corpus scenes (not the benchmark scenes) of the
# ratios POV-Ray / lucent: wall time, CPU time, peak memory.
if [ -f "$out/corpus-table" ]; then
	awk -F'\t' '
	function median(a, n,   i, j, t) {
		for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] > a[j]; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
		return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
	}
	NR > 1 && $7 > 0 && $9 > 0 {
		nw++; w[nw] = $12 / $7; sl += $7; sp += $12
		if ($8 > 0) { nc++; c[nc] = $13 / $8; cl += $8; cp += $13 }
		nm++; m[nm] = $14 / $9
	}
	END {
		if (!nw) exit
		printf "corpus: %d scenes; median ratio POV-Ray / lucent: wall %.2f, cpu %.2f, peak memory %.2f\n", nw, median(w, nw), nc ? median(c, nc) : 0, median(m, nm)
		printf "corpus totals: wall lucent %.2f s, POV-Ray %.2f s; cpu lucent %.2f s, POV-Ray %.2f s\n", sl, sp, cl, cp
	}' "$out/corpus-table"
fi

#!/bin/sh
# tests/bench/accuracy.sh: what accuracy costs in time, for lucent and
# POV-Ray 3.7 measured in the same run. Renders the scenes/acc-*.pov scenes
# at every setting listed in tests/bench/accuracy/sweeps.txt (antialiasing
# method, threshold, depth and jitter; area-light grid, adaptive level and
# jitter; focal blur samples, variance and confidence; max_trace_level;
# quality level), measures
#   time:  CPU seconds (user + system) of the render, one render thread
#          (+WT1) for both: the whole command's less that of the same
#          command at 1x1 pixels, the least of ACC_REPEATS runs for renders
#          under a second and of 3 for longer ones but the references (see
#          timed below);
#   error: RMS and largest difference over every pixel and channel, in
#          linear float (OpenEXR output, +FE), against the same renderer's
#          converged reference (the sweep's "reference" line),
# and writes doc/accuracy.md with a table per scene, a plot of error
# against time per scene (doc/images/accuracy/*.png, drawn by gnuplot,
# installed through apt-get when missing), the time each renderer needs to
# reach the same error, and the settings that reach the scene's preview and
# final error targets (sweeps.txt) the fastest. Asserts nothing; run by
# `make accuracy`.
#
# Environment: LUCENT (the binary), POVRAY (default povray), ACC_W, ACC_H
# (image size, default 320x240), ACC_REPEATS (default 5), ACC_SCENES (a
# space-separated subset, e.g. "checker glass"), ACC_DOC (default
# doc/accuracy.md; its images go to images/accuracy/ beside it), ACC_KEEP (a
# folder to keep the rendered images in), ACC_LUCENT_COMMIT (the commit
# LUCENT was built from, for the report; default the source tree's HEAD).
: "${top_srcdir:=$(cd "$(dirname "$0")/../.." && pwd)}"
: "${LUCENT:=$top_srcdir/lucent}"
: "${POVRAY:=povray}"
W=${ACC_W:-320}
H=${ACC_H:-240}
REPEATS=${ACC_REPEATS:-5}
DOC=${ACC_DOC:-$top_srcdir/doc/accuracy.md}
IMGDIR=$(dirname "$DOC")/images/accuracy
SWEEPS=$top_srcdir/tests/bench/accuracy/sweeps.txt
. "$top_srcdir/tests/bench/accuracy/lib.sh"

command -v idiff > /dev/null 2>&1 || { echo "accuracy.sh: idiff (openimageio-tools) is needed" >&2; exit 1; }
[ -x "$LUCENT" ] || { echo "accuracy.sh: no lucent binary at $LUCENT" >&2; exit 1; }
havepov=1
command -v "$POVRAY" > /dev/null 2>&1 || { echo "accuracy.sh: $POVRAY not found; lucent only" >&2; havepov=0; }

# gnuplot draws the plots; installed like build.sh installs the build's
# packages when missing (as root, or through sudo).
if ! command -v gnuplot > /dev/null 2>&1; then
	if [ "$(id -u)" = 0 ]; then SUDO=""; else SUDO="sudo"; fi
	echo "accuracy.sh: installing gnuplot-nox for the plots"
	{ $SUDO apt-get update && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y \
		--no-install-recommends gnuplot-nox; } > /dev/null 2>&1 ||
		echo "accuracy.sh: could not install gnuplot-nox; no plots" >&2
fi

if [ -n "$ACC_KEEP" ]; then
	out=$ACC_KEEP
	mkdir -p "$out" || exit 1
else
	out=$(mktemp -d "${TMPDIR:-/tmp}/lucent-accuracy.XXXXXX") || exit 1
	trap 'rm -rf "$out"' EXIT
fi
data=$out/results.tsv
: > "$data"
: > "$out/targets.tsv"

loadavg() { cut -d' ' -f1-3 /proc/loadavg 2>/dev/null; }
load_start=$(loadavg)
: "${ACC_LUCENT_COMMIT:=$(git -C "$top_srcdir" rev-parse --short HEAD 2>/dev/null)}"
LUCENT_DESC="built from commit ${ACC_LUCENT_COMMIT:-unknown}"
POV_DESC=$("$POVRAY" --version 2>&1 | sed -n 's/^\(POV-Ray [0-9][^ ]*\).*/\1/p' | head -n1)
started=$(date -u '+%Y-%m-%d %H:%M UTC')

# render_lucent SCENE SWITCHES IMG WxH: renders (IMG "-": no file written)
# and prints the CPU seconds it took (cputime.py), or fails leaving lucent's
# first error line in $out/why.
CPUTIME="/usr/bin/python3 $top_srcdir/tests/bench/accuracy/cputime.py"
render_lucent() {
	if [ "$3" = - ]; then o=-F; else o=+O$3; fi
	# shellcheck disable=SC2086
	$CPUTIME "$LUCENT" +I"$1" "$o" +W"${4%x*}" +H"${4#*x}" +WT1 $2 > "$out/log" 2>&1
	st=$?
	t=$(sed -n 's/^cputime \([0-9.]*\)$/\1/p' "$out/log")
	if [ $st -ne 0 ] || [ -z "$t" ]; then
		grep -m1 'error' "$out/log" > "$out/why" || head -n1 "$out/log" > "$out/why"
		return 1
	fi
	echo "$t"
}

# render_povray SCENE SWITCHES IMG WxH: the same for POV-Ray.
render_povray() {
	if [ "$3" = - ]; then o=-F; else o="+O$3 +FE"; fi
	# shellcheck disable=SC2086
	$CPUTIME "$POVRAY" +I"$1" $o +W"${4%x*}" +H"${4#*x}" -D +WT1 $2 > "$out/log" 2>&1
	st=$?
	t=$(sed -n 's/^cputime \([0-9.]*\)$/\1/p' "$out/log")
	if [ $st -ne 0 ] || [ -z "$t" ] || { [ "$3" != - ] && [ ! -s "$3" ]; }; then
		grep -m1 -i 'error\|problem' "$out/log" > "$out/why" || tail -n1 "$out/log" > "$out/why"
		return 1
	fi
	echo "$t"
}

# least N RENDERER SCENE SWITCHES IMG WxH: the least CPU time of N runs.
least() {
	k=$1; shift
	best=$(render_"$1" "$2" "$3" "$4" "$5") || return 1
	while [ "$k" -gt 1 ]; do
		t=$(render_"$1" "$2" "$3" "$4" "$5") || return 1
		best=$(awk -v a="$best" -v b="$t" 'BEGIN { print (b < a ? b : a) }')
		k=$((k - 1))
	done
	echo "$best"
}

# timed RENDERER SCENE SWITCHES IMG [once]: renders IMG and prints the CPU
# time of the render alone: the whole command's less that of the same
# command at 1x1 pixels (start-up, parsing, preparing, writing the file).
# A render that takes over a second is timed as the least of 3 runs (its
# IMG run and two more writing IMG again; with `once`, for the references,
# by its IMG run alone: a single run moved such times by 10 to 30% on a
# virtual machine); a shorter one by the least of REPEATS runs writing no
# file, less the least of REPEATS such runs at 1x1; a command under a
# quarter of a second by three times as many (its render, a few
# milliseconds, is within the noise of the start-up: the least of 3 moved
# such renders by a factor of 2 between runs).
timed() {
	whole=$(render_"$1" "$2" "$3" "$4" "${W}x$H") || return 1
	if awk -v t="$whole" 'BEGIN { exit !(t > 1) }'; then
		if [ "$5" != once ]; then
			more=$(least 2 "$1" "$2" "$3" "$4" "${W}x$H") || return 1
			whole=$(awk -v a="$whole" -v b="$more" 'BEGIN { print (b < a ? b : a) }')
		fi
		base=$(least 2 "$1" "$2" "$3" "$out/base.exr" 1x1) || return 1
	else
		k=$REPEATS
		awk -v t="$whole" 'BEGIN { exit !(t < 0.25) }' && k=$((3 * REPEATS))
		whole=$(least "$k" "$1" "$2" "$3" - "${W}x$H") || return 1
		base=$(least "$k" "$1" "$2" "$3" - 1x1) || return 1
	fi
	awk -v a="$whole" -v b="$base" 'BEGIN { d = a - b; printf "%.3f\n", (d > 0.001 ? d : 0.001) }'
}

printf 'accuracy: %dx%d, one render thread each, %s CPUs, load average %s\n' "$W" "$H" \
	"$(nproc)" "$load_start"
printf '%-11s %-40s %9s %9s %9s   %9s %9s %9s\n' scene setting l_time l_rms l_max p_time p_rms p_max
grep -v '^[[:space:]]*#' "$SWEEPS" | grep -v '^[[:space:]]*$' |
while IFS='|' read -r scene label switches; do
	scene=$(echo "$scene" | sed 's/^ *//; s/ *$//')
	label=$(echo "$label" | sed 's/^ *//; s/ *$//')
	switches=$(echo "$switches" | sed 's/^ *//; s/ *$//')
	if [ -n "$ACC_SCENES" ]; then
		case " $ACC_SCENES " in *" $scene "*) ;; *) continue ;; esac
	fi
	if [ "$label" = targets ]; then
		printf '%s\t%s\n' "$scene" "$switches" >> "$out/targets.tsv"
		continue
	fi
	pov=$top_srcdir/scenes/acc-$scene.pov
	n=$(awk -F'\t' -v s="$scene" '$1 == s { n++ } END { print n + 0 }' "$data")
	li=$out/$scene-l$n.exr
	pi=$out/$scene-p$n.exr
	lt=- lr=- lm=- pt=- pr=- pm=- lwhy="" pwhy=""
	once=""
	[ "$label" = reference ] && once=once
	if lt=$(timed lucent "$pov" "$switches" "$li" $once); then
		if [ "$label" != reference ]; then
			set -- $(acc_error "$out/$scene-l0.exr" "$li") - -
			lr=$1 lm=$2
		fi
	else
		lt=- lwhy=$(cat "$out/why")
	fi
	if [ $havepov = 1 ]; then
		if pt=$(timed povray "$pov" "$switches" "$pi" $once); then
			if [ "$label" != reference ]; then
				set -- $(acc_error "$out/$scene-p0.exr" "$pi") - -
				pr=$1 pm=$2
			fi
		else
			pt=- pwhy=$(cat "$out/why")
		fi
	fi
	printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$scene" "$label" "$switches" \
		"$lt" "$lr" "$lm" "$pt" "$pr" "$pm" "$lwhy" "$pwhy" >> "$data"
	printf '%-11s %-40.40s %9s %9s %9s   %9s %9s %9s\n' "$scene" "$label" "$lt" "$lr" "$lm" "$pt" "$pr" "$pm"
	[ -n "$lwhy" ] && echo "    lucent failed: $lwhy"
	[ -n "$pwhy" ] && echo "    POV-Ray failed: $pwhy"
done
load_end=$(loadavg)
echo "load average at the end: $load_end"

scenes=$(cut -f1 "$data" | awk '!seen[$0]++')
[ -n "$scenes" ] || { echo "accuracy.sh: nothing measured" >&2; exit 1; }

# How far apart the two renderers' references are (both linear EXR).
for s in $scenes; do
	if [ -f "$out/$s-l0.exr" ] && [ -f "$out/$s-p0.exr" ]; then
		printf '%s\t%s\n' "$s" "$(acc_error "$out/$s-p0.exr" "$out/$s-l0.exr")"
	fi
done > "$out/refdiff.tsv"

# front FILE: the settings no other setting beats on both time and error
# ("time rms" lines in, sorted by time out).
front() {
	sort -g -k1,1 -k2,2 "$1" | awk 'NR == 1 || $2 < best { print; best = $2 }'
}

# fastest SCENE COLUMN_TIME COLUMN_RMS TARGET: "label<TAB>time" of the
# fastest setting whose RMS is at most TARGET.
fastest() {
	awk -F'\t' -v s="$1" -v ct="$2" -v cr="$3" -v tg="$4" '
		$1 == s && $2 != "reference" && $ct != "-" && $cr != "" && $cr != "-" && $cr + 0 <= tg + 0 {
			if (best == "" || $ct + 0 < best + 0) { best = $ct; lab = $2 } }
		END { if (best != "") printf "%s\t%s\n", lab, best }' "$data"
}

# equal_error SCENE MODE: acc_compare (lib.sh) on the scene's settings.
equal_error() {
	awk -F'\t' -v s="$1" '
		$1 == s && $2 != "reference" {
			if ($4 != "-" && $5 != "-") print "l", $4, $5
			if ($7 != "-" && $8 != "-") print "p", $7, $8 }' "$data" | acc_compare "$2"
}

# Plots.
mkdir -p "$IMGDIR"
if command -v gnuplot > /dev/null 2>&1; then
	term="pngcairo size 720,450 font 'sans,10'"
	gnuplot -e "set terminal $term" -e "quit" > /dev/null 2>&1 || term="png size 720,450"
	for s in $scenes; do
		awk -F'\t' -v s="$s" '$1 == s && $2 != "reference" && $4 != "-" && $5 != "-" {
			print ($4 > 0.001 ? $4 : 0.001), ($5 > 1e-5 ? $5 : 1e-5) }' "$data" > "$out/$s-l.dat"
		awk -F'\t' -v s="$s" '$1 == s && $2 != "reference" && $7 != "-" && $8 != "-" {
			print ($7 > 0.001 ? $7 : 0.001), ($8 > 1e-5 ? $8 : 1e-5) }' "$data" > "$out/$s-p.dat"
		front "$out/$s-l.dat" > "$out/$s-lf.dat"
		front "$out/$s-p.dat" > "$out/$s-pf.dat"
		plots=""
		[ -s "$out/$s-l.dat" ] && plots="'$out/$s-l.dat' with points pt 7 ps 0.8 lc rgb '#1f77b4' title 'lucent (each setting)', '$out/$s-lf.dat' with lines lw 2 lc rgb '#1f77b4' title 'lucent (best settings)'"
		if [ -s "$out/$s-p.dat" ]; then
			[ -n "$plots" ] && plots="$plots, "
			plots="$plots'$out/$s-p.dat' with points pt 5 ps 0.8 lc rgb '#d62728' title 'POV-Ray (each setting)', '$out/$s-pf.dat' with lines lw 2 dt 2 lc rgb '#d62728' title 'POV-Ray (best settings)'"
		fi
		[ -n "$plots" ] || continue
		gnuplot <<-EOF
			set terminal $term
			set output '$IMGDIR/$s.png'
			set title 'acc-$s.pov at ${W}x${H}: error against render CPU time (one thread)'
			set logscale xy
			set format x '%g'
			set format y '%g'
			set grid
			set key top right
			set xlabel 'render CPU time (s)'
			set ylabel 'RMS error against the converged reference (linear)'
			plot $plots
		EOF
	done
fi

# doc/accuracy.md
{
	cat <<-EOF
	# What accuracy costs in time

	Generated by \`make accuracy\` (tests/bench/accuracy.sh) on $started.
	Reproduce with \`make accuracy\` (options in the script's header comment,
	e.g. \`make accuracy ACC_W=160 ACC_H=120 ACC_REPEATS=3\` for a quicker
	run); the settings are listed in tests/bench/accuracy/sweeps.txt and the
	scenes are scenes/acc-*.pov.

	## How it is measured

	- Image ${W}x${H}, one render thread for each renderer (\`+WT1\`), the same
	  switches for both (\`Declare=\` switches set the scene's own settings).
	- **Time**: CPU seconds (user + system, as the kernel accounts them to the
	  process and its threads) of the render alone: the whole command's less
	  that of the same command at 1x1 pixels, which leaves out start-up,
	  parsing, preparing and writing the file (the same whatever the setting).
	  CPU time rather than wall clock, so that other jobs on a shared machine
	  disturb the figures less. Renders under a second are timed as the least
	  of $REPEATS runs (and so is their 1x1 run), commands under a quarter of
	  a second as the least of $((3 * REPEATS)), longer ones as the least of 3
	  (the references: one run).
	- **Error**: RMS and largest absolute difference over every pixel and
	  channel, in linear float (OpenEXR output, \`+FE\`; POV-Ray writes half
	  floats, about 3 significant digits), computed by OpenImageIO's idiff,
	  against **the same renderer's** converged reference: the scene's
	  "reference" line, rendered at very high settings. Each renderer is thus
	  judged by how close it gets to what it would converge to; the last column
	  of the summary gives how far apart the two references are.
	- lucent: $LUCENT_DESC; POV-Ray: $POV_DESC.
	- Machine: $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -n1), $(nproc) CPUs; load average
	  (1, 5, 15 min) $load_start at the start and $load_end at the end.
	EOF
	if awk -v l="$load_start" -v m="$load_end" 'BEGIN { split(l, a, " "); split(m, b, " "); exit !(a[1] > 1 || b[1] > 1) }'; then
		cat <<-EOF
		  **These figures are from a loaded machine** (other jobs were running), so
		  CPU times suffer less from it than wall-clock times, but sharing the
		  caches still inflates them, and times under about 0.05 s are noisy; both
		  renderers ran in turn under the same load. Re-run on an idle machine for
		  firm figures.
		EOF
	fi
	cat <<-EOF

	## Summary

	**Same error, time compared.** For every error level that one of the
	renderers' settings reaches, the time each renderer needs to get there,
	and the ratio of POV-Ray's time over lucent's: above 1 means lucent's
	curve lies below POV-Ray's (less time for the same error). Two ways:
	- *settings*: the fastest measured setting with at most that RMS error
	  (a step: a level just below one renderer's setting counts that
	  renderer's next, much slower setting, so one setting a few percent
	  worse in error at equal switches gives a low ratio there);
	- *curves*: on the curves of the plots, each renderer's fastest
	  settings joined by straight lines on the log-log scale.
	"Only lucent" / "only POV-Ray" count the levels that only one of them
	reaches with the settings measured.

	| scene | settings: median | lowest | highest | curves: median | lowest | highest | levels compared | only lucent | only POV-Ray | the two references differ by (RMS, max) |
	|---|---|---|---|---|---|---|---|---|---|---|
	EOF
	for s in $scenes; do
		rd=$(awk -F'\t' -v s="$s" '$1 == s { split($2, a, " "); print a[1] ", " a[2] }' "$out/refdiff.tsv")
		line=$(equal_error "$s" line)
		set -- $(equal_error "$s" step)
		printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$s" "$1" "$2" "$3" \
			$(echo "$line" | cut -d' ' -f1-3) "$4" "$5" "$6" "${rd:--}"
	done
	cat <<-EOF

	**Recommended settings.** Per scene, the fastest measured setting that
	reaches the scene's preview and final RMS targets (set in sweeps.txt from
	what the scene's errors span; linear units, 0.005 is about 1/255 of the
	display range in the mid-tones). "-" means no measured setting got there.

	| scene | use (RMS target) | lucent: setting | CPU (s) | POV-Ray: setting | CPU (s) |
	|---|---|---|---|---|---|
	EOF
	for s in $scenes; do
		tgs=$(awk -F'\t' -v s="$s" '$1 == s { print $2 }' "$out/targets.tsv")
		[ -n "$tgs" ] || continue
		set -- $tgs
		for tg in "preview $1" "final $2"; do
			v=${tg#* }
			l=$(fastest "$s" 4 5 "$v")
			p=$(fastest "$s" 7 8 "$v")
			printf '| %s | %s (%s) | %s | %s | %s | %s |\n' "$s" "${tg% *}" "$v" \
				"${l%	*}" "${l#*	}" "${p%	*}" "${p#*	}" | sed 's/|  |/| - |/g; s/|  |/| - |/g'
		done
	done
	echo
	for s in $scenes; do
		echo "## acc-$s.pov"
		echo
		sed -n '1,/^#version/p' "$top_srcdir/scenes/acc-$s.pov" | grep '^//' | sed 's|^// \{0,1\}||'
		echo
		echo "| setting | switches | lucent CPU (s) | lucent RMS | lucent max | POV-Ray CPU (s) | POV-Ray RMS | POV-Ray max |"
		echo "|---|---|---|---|---|---|---|---|"
		awk -F'\t' -v s="$s" '$1 == s { printf "| %s | `%s` | %s | %s | %s | %s | %s | %s |\n", $2, $3, $4, $5, $6, $7, $8, $9 }' "$data"
		awk -F'\t' -v s="$s" '$1 == s && $10 != "" { printf "\nlucent failed on \"%s\": `%s`\n", $2, $10 }
			$1 == s && $11 != "" { printf "\nPOV-Ray failed on \"%s\": `%s`\n", $2, $11 }' "$data"
		if [ -f "$IMGDIR/$s.png" ]; then
			echo
			echo "![error against time, acc-$s.pov](images/accuracy/$s.png)"
		fi
		echo
	done
	notes=$top_srcdir/tests/bench/accuracy/notes.md
	[ -f "$notes" ] && cat "$notes"
} > "$DOC"
echo "accuracy.sh: wrote $DOC and $IMGDIR/"

#!/bin/sh
# lucent-regress: render a corpus of scenes with lucent, in parallel, and
# compare each image
#  - with lucent's expected image, exactly unless the scene's limits say
#    otherwise (rendering is deterministic: a changed pixel is a
#    regression, or a deliberate change to be refreshed and committed);
#  - with POV-Ray 3.7's render of the same scene at the same switches,
#    within the scene's limits (default: no channel of any pixel off by
#    more than 1/255).
# Prints a summary (pass/fail per scene, worst first, then the totals),
# writes an HTML report (lucent's and POV-Ray's images, a heat map of
# their difference, the error figures and both renderers' times) and
# exits 1 if any scene fails. With --refresh it renders the references
# instead. Images are compared through OpenImageIO's oiiotool.
# The corpus format, the limits and the report: doc/regress.md.
# (lucent --regress ARGS runs this script.)
# The results are read back with eval and ".":
# shellcheck disable=SC2154,SC1090

usage() {
	cat << 'EOF'
Usage: lucent-regress [OPTION]... [DIR | LIST]...
Render the scenes of a corpus with lucent (in parallel), compare each image
with lucent's expected image (exactly, unless the scene's limits say
otherwise) and with POV-Ray's render (within the scene's limits), print a
summary worst first, write an HTML report, and exit 1 if any scene fails.

A LIST is a file of lines "NAME WIDTH HEIGHT [LIMITS] [| SWITCHES]"; a DIR
stands for its *.list files, or, if it has none, for its *.pov scenes at
160x120. The references of a list's scenes are in the list's folder:
expected/NAME.png (lucent's), povray/NAME.png and povray/NAME.time
(POV-Ray's image and render time). Without DIR or LIST: tests/render (with
the scenes in scenes/) if it exists, else the current folder.

  -j, --jobs N        run N renders at once (default: the number of cores);
                      each render uses one thread
  -o, --output DIR    write the HTML report to DIR/index.html and DIR/images/
                      (default: regress-report)
      --no-report     write no HTML report
  -s, --scenes DIR    find NAME.pov in DIR (default: the list's folder)
  -e, --expected DIR  lucent's expected images (default: LISTDIR/expected)
  -p, --povray DIR    POV-Ray's images and times (default: LISTDIR/povray)
  -n, --name PATTERN  only the scenes whose name matches the shell pattern
                      (may be given more than once)
  -q, --quiet         print only the failing scenes and the totals
      --refresh[=WHAT]  render the references of the selected scenes instead
                      of comparing: WHAT is all (default: POV-Ray's image and
                      time, and lucent's expected image), lucent, povray, or
                      times (POV-Ray's time only, its image left as it is)
  -h, --help          show this help

Environment: LUCENT (default: the lucent beside this script, else lucent),
POVRAY (default povray), OIIOTOOL (default oiiotool).
Exit status: 0 every scene passed, 1 a scene failed, 2 usage error.
EOF
}

die() {
	echo "lucent-regress: error: $*" >&2
	exit 2
}

# --- Options -------------------------------------------------------------
jobs=""
report=regress-report
scenedir=""
expdir=""
povdir=""
names=""
quiet=0
refresh=""
# Options may come before or after the DIR and LIST operands: each
# argument is taken from the front, and an operand is put back at the end.
n=$#
while [ "$n" -gt 0 ]; do
	arg=$1
	shift
	n=$((n - 1))
	case $arg in
	-j | --jobs | -o | --output | -s | --scenes | -e | --expected | -p | --povray | -n | --name)
		[ "$n" -ge 1 ] || die "$arg needs a value"
		val=$1
		shift
		n=$((n - 1))
		case $arg in
		-j | --jobs) jobs=$val ;;
		-o | --output) report=$val ;;
		-s | --scenes) scenedir=$val ;;
		-e | --expected) expdir=$val ;;
		-p | --povray) povdir=$val ;;
		-n | --name) names="$names $val" ;;
		esac ;;
	-j*) jobs=${arg#-j} ;;
	--jobs=*) jobs=${arg#*=} ;;
	--output=*) report=${arg#*=} ;;
	--no-report) report="" ;;
	--scenes=*) scenedir=${arg#*=} ;;
	--expected=*) expdir=${arg#*=} ;;
	--povray=*) povdir=${arg#*=} ;;
	--name=*) names="$names ${arg#*=}" ;;
	-q | --quiet) quiet=1 ;;
	--refresh) refresh=all ;;
	--refresh=*)
		refresh=${arg#*=}
		case $refresh in all | lucent | povray | times) ;;
		*) die "--refresh=$refresh: expected all, lucent, povray or times" ;;
		esac ;;
	-h | --help) usage; exit 0 ;;
	--)
		while [ "$n" -gt 0 ]; do
			set -- "$@" "$1"
			shift
			n=$((n - 1))
		done ;;
	-?*) die "unknown option '$arg' (see lucent-regress --help)" ;;
	*) set -- "$@" "$arg" ;;
	esac
done
case $jobs in
'') jobs=$(nproc 2> /dev/null || getconf _NPROCESSORS_ONLN 2> /dev/null || echo 1) ;;
*[!0-9]* | 0) die "-j $jobs: expected a positive whole number" ;;
esac

if [ -z "${LUCENT:-}" ]; then
	LUCENT=lucent
	here=$(dirname "$0")
	[ -x "$here/lucent" ] && [ ! -d "$here/lucent" ] && LUCENT=$here/lucent
fi
POVRAY=${POVRAY:-povray}
OIIOTOOL=${OIIOTOOL:-oiiotool}
case $refresh in povray | times) ;;
*) command -v "$LUCENT" > /dev/null 2>&1 || die "lucent not found ($LUCENT): set LUCENT" ;;
esac
if [ "$refresh" = "" ] || [ "$refresh" = lucent ]; then
	command -v "$OIIOTOOL" > /dev/null 2>&1 ||
		die "oiiotool (OpenImageIO) not found ($OIIOTOOL): set OIIOTOOL"
fi
if [ "$refresh" != "" ] && [ "$refresh" != lucent ]; then
	command -v "$POVRAY" > /dev/null 2>&1 || die "povray not found ($POVRAY): set POVRAY"
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/lucent-regress.XXXXXX") || exit 2
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
US=$(printf '\037')
# No file name expansion except where a glob is meant (set +f there).
set -f

# now: the wall-clock time in seconds (to the nanosecond where date has %N).
now() {
	t=$(date +%s.%N)
	case $t in *N) date +%s ;; *) echo "$t" ;; esac
}

# diff_secs A B: B - A, to the hundredth.
diff_secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f\n", b - a }'; }

# Times are also the CPU time (user + system) a renderer took, from the
# shell's "times", which does not depend on how busy the machine is: the jobs
# run in subshells, whose children's times start at 0.
# cpu_mark FILE: save the times so far (not in a $(...) subshell, whose
# times start at 0); cpu_diff FILE0 FILE1: the seconds between two marks.
cpu_mark() { times > "$1"; }
cpu_diff() {
	awk 'function secs(f, m) { m = f; sub(/m.*/, "", m); sub(/^[0-9]*m/, "", f); sub(/s$/, "", f); return m * 60 + f }
		NR == 2 { t0 = secs($1) + secs($2) }
		NR == 4 { printf "%.2f\n", secs($1) + secs($2) - t0 }' "$1" "$2"
}

# sq TEXT: TEXT quoted for the shell, in single quotes.
sq() { printf "'%s'" "$(printf '%s' "$1" | sed "s/'/'\\\\''/g")"; }

# --- The scenes ------------------------------------------------------------
# Each selected scene becomes one line of $tmp/scenes, fields separated by
# US: name, width, height, POV-Ray limits, expected limits, switches, scene
# file, expected image folder, POV-Ray folder, where it was listed.
if [ $# -eq 0 ]; then
	if [ -d tests/render ] && [ -z "$scenedir" ] && [ -d scenes ]; then
		scenedir=scenes
		set -- tests/render
	else
		set -- .
	fi
fi

# wanted NAME: does the name match a -n pattern (or is there none)?
wanted() {
	[ -z "$names" ] && return 0
	for pat in $names; do
		# shellcheck disable=SC2254 # the pattern is meant to match
		case $1 in $pat) return 0 ;; esac
	done
	return 1
}

# add_list FILE: the scenes of a list file.
add_list() {
	ldir=$(dirname "$1")
	lineno=0
	while IFS= read -r line || [ -n "$line" ]; do
		lineno=$((lineno + 1))
		sw=""
		case $line in *'|'*) sw=${line#*|}; line=${line%%|*} ;; esac
		# shellcheck disable=SC2086 # split the line into words
		set -- $line
		case ${1:-#} in '#'*) continue ;; esac
		[ $# -ge 3 ] || die "$list:$lineno: expected NAME WIDTH HEIGHT"
		name=$1 w=$2 h=$3
		shift 3
		case $w$h in *[!0-9]*) die "$list:$lineno: bad size '$w $h'" ;; esac
		wanted "$name" || continue
		# The limits: idiff's options; those after "expected:" are for the
		# comparison with lucent's expected image.
		popts="" eopts="" which=p
		while [ $# -gt 0 ]; do
			case $1 in
			expected:) which=e; shift; continue ;;
			-fail | -failpercent | -hardfail | -warn | -warnpercent | -hardwarn | \
			--fail | --failpercent | --hardfail | --warn | --warnpercent | --hardwarn)
				[ $# -ge 2 ] || die "$list:$lineno: $1 needs a value"
				opt=${1#-}
				opt=-${opt#-}
				case $2 in
				*[!0-9.eE+-]* | '') die "$list:$lineno: $1 $2: expected a number" ;;
				esac
				if [ $which = p ]; then popts="${popts:+$popts }$opt $2"; else eopts="${eopts:+$eopts }$opt $2"; fi
				shift 2 ;;
			*) die "$list:$lineno: unknown limit '$1' (expected -fail, -failpercent, -hardfail, -warn, -warnpercent, -hardwarn or expected:)" ;;
			esac
		done
		sd=${scenedir:-$ldir}
		printf '%s\n' "$name$US$w$US$h$US$popts$US$eopts$US$sw$US$sd/$name.pov$US${expdir:-$ldir/expected}$US${povdir:-$ldir/povray}$US$list:$lineno"
	done < "$1"
}

: > "$tmp/scenes"
args="$*"
for arg in "$@"; do
	if [ -d "$arg" ]; then
		set +f
		set -- "$arg"/*.list
		set -f
		if [ -f "$1" ]; then
			for list in "$@"; do add_list "$list" >> "$tmp/scenes" || exit 2; done
		else
			set +f
			set -- "$arg"/*.pov
			set -f
			for scene in "$@"; do
				[ -f "$scene" ] || continue
				name=$(basename "$scene" .pov)
				wanted "$name" || continue
				printf '%s\n' "$name${US}160${US}120$US$US$US$US${scenedir:-$arg}/$name.pov$US${expdir:-$arg/expected}$US${povdir:-$arg/povray}$US$scene"
			done >> "$tmp/scenes"
		fi
	elif [ -f "$arg" ]; then
		list=$arg
		add_list "$list" >> "$tmp/scenes" || exit 2
	else
		die "$arg: no such file or folder"
	fi
done
[ -s "$tmp/scenes" ] || die "no scene selected${names:+ (-n$names)} in $args"
# A name names the references and the report's images: it must be unique.
dups=$(cut -d"$US" -f1 "$tmp/scenes" | sort | uniq -d | tr '\n' ' ')
[ -z "$dups" ] || die "listed more than once: $dups"
for pat in $names; do
	found=0
	while IFS=$US read -r name rest; do
		# shellcheck disable=SC2254
		case $name in $pat) found=1; break ;; esac
	done < "$tmp/scenes"
	[ $found -eq 1 ] || die "-n $pat: no such scene in $args"
done

# --- Running jobs in parallel ---------------------------------------------
# A FIFO holds one token per free slot: a job takes one before it starts
# and gives it back when it ends.
mkfifo "$tmp/slots" || exit 2
exec 3<> "$tmp/slots"
i=0
while [ $i -lt "$jobs" ]; do echo >&3; i=$((i + 1)); done

# each FUNCTION: run FUNCTION with the fields of every scene, $jobs at once.
each() {
	while IFS=$US read -r name w h popts eopts sw scene exp pov where; do
		read -r _ <&3
		( "$1" "$name" "$w" "$h" "$popts" "$eopts" "$sw" "$scene" "$exp" "$pov" "$where"
		echo >&3 ) < /dev/null &
	done < "$tmp/scenes"
	wait
}

# --- Refreshing the references ---------------------------------------------
# refresh_scene FIELDS...: render the scene's references.
refresh_scene() {
	name=$1 w=$2 h=$3 sw=$6 scene=$7 exp=$8 pov=$9
	log=$tmp/$name.log
	msg=""
	if [ ! -f "$scene" ]; then
		echo "$name: no $scene" > "$tmp/$name.fail"
		return
	fi
	if [ "$refresh" != lucent ]; then
		mkdir -p "$pov"
		out=$pov/$name.png
		[ "$refresh" = times ] && out=$tmp/$name-povray.png
		cpu_mark "$tmp/$name.t"
		w0=$(now)
		# shellcheck disable=SC2086 # the switches are meant to be split
		if "$POVRAY" -D -V +WT1 +W"$w" +H"$h" $sw +I"$scene" +O"$out" > "$log" 2>&1; then
			w1=$(now)
			cpu_mark "$tmp/$name.t1"
			secs=$(cpu_diff "$tmp/$name.t" "$tmp/$name.t1")
			wall=$(diff_secs "$w0" "$w1")
			echo "$secs $wall: POV-Ray's CPU time (user + system) and wall-clock time in seconds, $w x $h${sw:+ $sw} +WT1" \
				> "$pov/$name.time"
			msg="POV-Ray $secs s CPU, $wall s wall"
		else
			{ echo "$name: povray failed:"; sed 's/^/  /' "$log"; } > "$tmp/$name.fail"
		fi
	fi
	if [ "$refresh" = all ] || [ "$refresh" = lucent ]; then
		mkdir -p "$exp"
		# shellcheck disable=SC2086
		if "$LUCENT" -q +WT1 +W"$w" +H"$h" $sw "$scene" +O"$exp/$name.png" > "$log" 2>&1; then
			[ -s "$log" ] && sed "s/^/$name: /" "$log"
		else
			{ echo "$name: lucent failed:"; sed 's/^/  /' "$log"; } >> "$tmp/$name.fail"
		fi
	fi
	[ -f "$tmp/$name.fail" ] || echo "$name: ${w}x$h done${msg:+ ($msg)}"
}

if [ -n "$refresh" ]; then
	each refresh_scene
	status=0
	set +f
	set -- "$tmp"/*.fail
	set -f
	for f in "$@"; do
		[ -f "$f" ] || continue
		cat "$f" >&2
		status=1
	done
	exit $status
fi

# --- Comparing ---------------------------------------------------------------
# figures PREFIX LOG: shell assignments PREFIX_mean, _rms, _psnr, _max,
# _maxat, _n1, _p1, _t1 (pixels over the warning threshold), _n2, _p2, _t2
# (over the failure threshold) and _verdict (PASS, WARNING or FAIL; oiiotool
# prints FAILURE) from
# oiiotool -v --diff's report.
figures() {
	sed -n \
		-e "s/^ *Mean error = *\\([^ ]*\\).*/$1_mean=\\1/p" \
		-e "s/^ *RMS error = *\\([^ ]*\\).*/$1_rms=\\1/p" \
		-e "s/^ *Peak SNR = *\\([^ ]*\\).*/$1_psnr=\\1/p" \
		-e "s/^ *Max error *= *\\([^ ]*\\) @ (\\([^)]*\\)).*/$1_max=\\1 $1_maxat='\\2'/p" \
		-e "s/^ *Max error *= *\\([^ ]*\\) *$/$1_max=\\1/p" \
		-e "s/^PASS\$/$1_verdict=PASS/p" -e "s/^WARNING\$/$1_verdict=WARNING/p" \
		-e "s/^FAIL\$/$1_verdict=FAIL/p" -e "s/^FAILURE\$/$1_verdict=FAIL/p" "$2"
	sed -n 's/^ *\([0-9]*\) pixels (\([^%]*\)%) over \([^ ]*\).*/\1 \2 \3/p' "$2" |
		awk -v p="$1" '{ printf "%s_n%d=%s %s_p%d=%s %s_t%d=%s\n", p, NR, $1, p, NR, $2, p, NR, $3 }'
}

# compare_scene FIELDS...: render the scene, compare it, and write the
# result as shell assignments to $tmp/NAME.res.
compare_scene() {
	name=$1 w=$2 h=$3 popts=$4 eopts=$5 sw=$6 scene=$7 exp=$8 pov=$9
	shift 9
	where=$1
	out=$tmp/$name.png
	res=$tmp/$name.res
	{
		echo "name=$(sq "$name") size=${w}x$h switches=$(sq "$sw") where=$(sq "$where")"
		echo "popts=$(sq "$popts") eopts=$(sq "$eopts")"
	} > "$res"
	if [ ! -f "$scene" ]; then
		echo "class=4 why=$(sq "no scene file $scene")" >> "$res"
		return
	fi
	cpu_mark "$tmp/$name.t"
	w0=$(now)
	# shellcheck disable=SC2086 # the switches are meant to be split
	if ! "$LUCENT" -q +WT1 +W"$w" +H"$h" $sw "$scene" +O"$out" > "$tmp/$name.log" 2>&1; then
		echo "class=4 why=$(sq "lucent failed: $(tr '\n' ' ' < "$tmp/$name.log")")" >> "$res"
		return
	fi
	w1=$(now)
	cpu_mark "$tmp/$name.t1"
	echo "ltime=$(cpu_diff "$tmp/$name.t" "$tmp/$name.t1") lwall=$(diff_secs "$w0" "$w1")" >> "$res"
	# POV-Ray's times, "CPU WALL: comment", as --refresh wrote them.
	[ -f "$pov/$name.time" ] &&
		awk 'NR == 1 { sub(/:.*/, ""); if ($1 ~ /^[0-9.]+$/) print "ptime=" $1; if ($2 ~ /^[0-9.]+$/) print "pwall=" $2 }' \
			"$pov/$name.time" >> "$res"
	missing=""
	for f in "$exp/$name.png" "$pov/$name.png"; do
		[ -f "$f" ] || missing="$missing $f"
	done
	[ -n "$missing" ] && echo "class=3 why=$(sq "missing$missing (run lucent-regress --refresh -n $name)")" >> "$res"
	# (a) lucent's expected image: the same file means the same pixels.
	if [ -f "$exp/$name.png" ]; then
		echo "expimg=$(sq "$exp/$name.png")" >> "$res"
		if cmp -s "$exp/$name.png" "$out"; then
			echo "e_verdict=SAME" >> "$res"
		else
			# shellcheck disable=SC2086 # the limits are meant to be split
			"$OIIOTOOL" -v --fail 0 --failpercent 0 --warn 0 --warnpercent 100 \
				$eopts "$exp/$name.png" "$out" --diff --absdiff --chsum --mulc 4 \
				--clamp:min=0:max=1 --powc 0.5 --colormap inferno -o "$tmp/$name-expdiff.png" \
				> "$tmp/$name.elog" 2>&1
			figures e "$tmp/$name.elog" >> "$res"
			grep -Eq '^(PASS|WARNING|FAIL|FAILURE)$' "$tmp/$name.elog" ||
				echo "e_error=$(sq "$(grep -Ev '^(Reading|Writing|Computing) ' "$tmp/$name.elog" | tr '\n' ' ')")" >> "$res"
		fi
	fi
	# (b) POV-Ray's image, within the scene's limits; the warning
	# threshold stays at 1/255 so that the count over it is reported.
	if [ -f "$pov/$name.png" ]; then
		echo "povimg=$(sq "$pov/$name.png")" >> "$res"
		# shellcheck disable=SC2086
		"$OIIOTOOL" -v --fail 0.004 --failpercent 0 --warn 0.004 --warnpercent 100 \
			$popts "$pov/$name.png" "$out" --diff --absdiff --chsum --mulc 4 \
			--clamp:min=0:max=1 --powc 0.5 --colormap inferno -o "$tmp/$name-diff.png" \
			> "$tmp/$name.plog" 2>&1
		figures p "$tmp/$name.plog" >> "$res"
		grep -Eq '^(PASS|WARNING|FAIL|FAILURE)$' "$tmp/$name.plog" ||
			echo "p_error=$(sq "$(grep -Ev '^(Reading|Writing|Computing) ' "$tmp/$name.plog" | tr '\n' ' ')")" >> "$res"
	fi
}

each compare_scene

# --- The summary -------------------------------------------------------------
# load NAME: the result's variables, with the class and the score that
# orders the scenes: 4 lucent failed, 3 a reference is missing, 2 differs
# from the expected image, 1 too far from POV-Ray, 0 passed; within a
# class, by the RMS error of the failing comparison (else POV-Ray's), then
# by the other comparison's.
load() {
	for v in name size switches where popts eopts class why ltime lwall ptime pwall expimg povimg; do
		eval "$v=''"
	done
	for p in e p; do
		for v in mean rms psnr max maxat n1 p1 t1 n2 p2 t2 verdict error; do
			eval "${p}_$v=''"
		done
	done
	. "$1"
	if [ -z "$class" ]; then
		class=0
		if [ -n "$e_error" ] || [ "$e_verdict" = FAIL ]; then
			class=2
		elif [ -n "$p_error" ] || [ "$p_verdict" = FAIL ]; then
			class=1
		fi
	fi
	case $class in
	2) score=${e_rms:-0} score2=${p_rms:-0} ;;
	*) score=${p_rms:-0} score2=${e_rms:-0} ;;
	esac
}

# over PREFIX: "N px (P%) > T" for the warning and failure thresholds.
over() {
	eval "n1=\$${1}_n1 p1=\$${1}_p1 t1=\$${1}_t1 n2=\$${1}_n2 p2=\$${1}_p2 t2=\$${1}_t2"
	[ "$t1" = 0.004 ] && t1=1/255
	[ "$t2" = 0.004 ] && t2=1/255
	s="$n1 px ($p1%) > $t1"
	[ "$t2" != "$t1" ] && [ -n "$t2" ] && s="$s, $n2 px ($p2%) > $t2"
	echo "$s"
}

: > "$tmp/order"
set +f
set -- "$tmp"/*.res
set -f
for f in "$@"; do
	load "$f"
	awk -v c="$class" -v s="$score" -v t="$score2" -v f="$f" \
		'BEGIN { printf "%d %.9f %.9f %s\n", c, s, t, f }' >> "$tmp/order"
done
sort -k1,1nr -k2,2nr -k3,3nr -k4,4 "$tmp/order" > "$tmp/sorted"

npass=0
nfail=0
sums="0 0 0 0"
ntimed=0
while read -r class score score2 f; do
	load "$f"
	why_e=""
	why_p=""
	case $class in
	4 | 3) line="$why" ;;
	*)
		if [ "$e_verdict" != SAME ]; then
			if [ -n "$e_error" ]; then
				why_e="cannot compare with $expimg: $e_error"
			elif [ "$e_verdict" = FAIL ]; then
				why_e="differs from $expimg: mean $e_mean, max $e_max, $(over e)"
			else
				why_e="within limits of $expimg ($eopts): mean $e_mean, max $e_max, $(over e)"
			fi
		fi
		if [ -n "$p_error" ]; then
			why_p="cannot compare with $povimg: $p_error"
		else
			why_p="vs POV-Ray: mean $p_mean, RMS $p_rms, max $p_max, $(over p), PSNR $p_psnr"
			[ "$p_verdict" = FAIL ] && why_p="too far from POV-Ray (${popts:--fail 0.004 -failpercent 0}): ${why_p#vs POV-Ray: }"
		fi
		line="${why_e:+$why_e; }$why_p"
		;;
	esac
	times="CPU lucent ${ltime:-?} s, POV-Ray ${ptime:-?} s"
	if [ -n "$ltime" ] && [ -n "$ptime" ]; then
		sums=$(awk -v s="$sums" -v a="$ltime" -v b="$ptime" -v c="${lwall:-0}" -v d="${pwall:-0}" \
			'BEGIN { split(s, t, " "); printf "%.2f %.2f %.2f %.2f", t[1] + a, t[2] + b, t[3] + c, t[4] + d }')
		ntimed=$((ntimed + 1))
	fi
	if [ "$class" -eq 0 ]; then
		npass=$((npass + 1))
		[ $quiet -eq 1 ] || echo "PASS: $name $size: $line; $times"
	else
		nfail=$((nfail + 1))
		echo "FAIL: $name $size: $line; $times"
	fi
	echo "$class $f" >> "$tmp/report.order"
done < "$tmp/sorted"

# shellcheck disable=SC2086 # the sums are meant to be split
set -- $sums
lsum=$1 psum=$2 lwsum=$3 pwsum=$4
echo "Totals: $((npass + nfail)) scenes, $npass passed, $nfail failed; the $ntimed scenes timed by both renderers (one thread each) took lucent $lsum s CPU ($lwsum s wall), POV-Ray $psum s CPU ($pwsum s wall)"

# --- The HTML report ---------------------------------------------------------
# esc: the text on stdin escaped for HTML.
esc() { sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g' -e 's/"/\&quot;/g'; }

# row LABEL PREFIX: a table row of one comparison's figures.
row() {
	eval "mean=\$${2}_mean rms=\$${2}_rms max=\$${2}_max maxat=\$${2}_maxat psnr=\$${2}_psnr verdict=\$${2}_verdict err=\$${2}_error"
	if [ "$verdict" = SAME ]; then
		echo "<tr><td>$1</td><td colspan=\"6\">identical</td></tr>"
	elif [ -n "$err" ]; then
		echo "<tr><td>$1</td><td colspan=\"6\">$(printf '%s' "$err" | esc)</td></tr>"
	elif [ -n "$verdict" ]; then
		echo "<tr><td>$1</td><td>$mean</td><td>$rms</td><td>$max${maxat:+ at ($maxat)}</td><td>$(over "$2" | esc)</td><td>$psnr</td><td class=\"$verdict\">$verdict</td></tr>"
	fi
}

if [ -n "$report" ]; then
	mkdir -p "$report/images" || die "cannot create $report/images"
	rm -f "$report"/images/*.png
	{
		cat << EOF
<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<title>lucent-regress: $npass passed, $nfail failed</title>
<style>
body { font-family: sans-serif; margin: 1em 2em; }
section { border-top: 1px solid #aaa; padding: 0.5em 0; }
h2 { font-size: 1.1em; margin: 0.3em 0; }
h2 .s0 { color: #070; } h2 .s1, h2 .s2, h2 .s3, h2 .s4 { color: #b00; }
figure { display: inline-block; margin: 0 1em 0.5em 0; vertical-align: top; }
figcaption { font-size: 0.85em; color: #444; }
img { image-rendering: pixelated; background: repeating-conic-gradient(#ccc 0 25%, #fff 0 50%) 0 0 / 16px 16px; }
table { border-collapse: collapse; font-size: 0.9em; }
td, th { border: 1px solid #ccc; padding: 0.15em 0.5em; text-align: left; }
td.FAIL { color: #b00; font-weight: bold; } td.PASS { color: #070; } td.WARNING { color: #a60; }
.note { font-size: 0.9em; color: #444; }
</style></head><body>
<h1>lucent-regress: $npass passed, $nfail failed</h1>
<p>$((npass + nfail)) scenes, worst first. The $ntimed scenes timed by both renderers
(one thread each) took lucent $lsum s CPU ($lwsum s wall-clock), POV-Ray $psum s CPU
($pwsum s wall-clock).
Generated $(date '+%Y-%m-%d %H:%M:%S') with $(printf '%s' "$LUCENT" | esc).</p>
<p class="note">Each scene: lucent's image now, POV-Ray's reference, and a heat map of their
difference (black: equal; the colour runs through purple and orange to pale yellow
as the sum of the channels' errors grows from 0 to 0.25, on a square-root scale, so
that one step of 1/255 shows). Errors are on 0..1 channel values: mean, RMS and max
absolute error; pixels over the thresholds (1/255, and the scene's failure threshold);
PSNR in dB. Times are CPU seconds (user + system) and wall-clock seconds of the whole
run of each renderer (parsing, rendering and writing the image) with one thread; lucent's
was measured in this run, POV-Ray's when its reference was rendered (lucent-regress
--refresh). Wall-clock times depend on how busy the machine was.</p>
<table>
<tr><th>scene</th><th>result</th><th>vs expected: max</th><th>vs POV-Ray: RMS</th><th>max</th><th>pixels over</th><th>PSNR (dB)</th><th>lucent CPU (s)</th><th>POV-Ray CPU (s)</th></tr>
EOF
		# The index: one row per scene, linking to its section.
		while read -r class f; do
			load "$f"
			[ "$class" -eq 0 ] && st=PASS || st=FAIL
			case $e_verdict in
			SAME) emax=0 ;;
			'') emax="" ;;
			*) emax=$e_max ;;
			esac
			echo "<tr><td><a href=\"#$name\">$name</a></td><td class=\"$st\">$st</td><td>$emax</td><td>$p_rms</td><td>$p_max</td><td>${p_n1:+$(over p | esc)}</td><td>$p_psnr</td><td>$ltime</td><td>$ptime</td></tr>"
		done < "$tmp/report.order"
		echo "</table>"
		while read -r class f; do
			load "$f"
			[ "$class" -eq 0 ] && st=PASS || st=FAIL
			cp "$tmp/$name.png" "$report/images/$name.png" 2> /dev/null
			[ -n "$povimg" ] && cp "$povimg" "$report/images/$name-povray.png"
			[ -f "$tmp/$name-diff.png" ] && cp "$tmp/$name-diff.png" "$report/images/$name-diff.png"
			echo "<section id=\"$name\">"
			echo "<h2><span class=\"s$class\">$st</span> $name <small>$size${switches:+ | $(printf '%s' "$switches" | esc)} &mdash; $(printf '%s' "$where" | esc)</small></h2>"
			[ -n "$why" ] && echo "<p>$(printf '%s' "$why" | esc)</p>"
			[ -f "$report/images/$name.png" ] && echo "<figure><img src=\"images/$name.png\" alt=\"lucent\"><figcaption>lucent</figcaption></figure>"
			[ -f "$report/images/$name-povray.png" ] && echo "<figure><img src=\"images/$name-povray.png\" alt=\"POV-Ray\"><figcaption>POV-Ray 3.7</figcaption></figure>"
			[ -f "$report/images/$name-diff.png" ] && echo "<figure><img src=\"images/$name-diff.png\" alt=\"difference\"><figcaption>difference (heat map)</figcaption></figure>"
			if [ -f "$tmp/$name-expdiff.png" ]; then
				cp "$expimg" "$report/images/$name-expected.png"
				cp "$tmp/$name-expdiff.png" "$report/images/$name-expdiff.png"
				echo "<figure><img src=\"images/$name-expected.png\" alt=\"expected\"><figcaption>lucent's expected image</figcaption></figure>"
				echo "<figure><img src=\"images/$name-expdiff.png\" alt=\"difference from expected\"><figcaption>now vs expected (heat map)</figcaption></figure>"
			fi
			if [ -n "$e_verdict$p_verdict$e_error$p_error" ]; then
				echo "<table><tr><th>compared with</th><th>mean</th><th>RMS</th><th>max</th><th>pixels over</th><th>PSNR (dB)</th><th>result</th></tr>"
				row "lucent's expected image${eopts:+ ($eopts)}" e
				row "POV-Ray (${popts:--fail 0.004 -failpercent 0})" p
				echo "</table>"
			fi
			if [ -n "$ltime$ptime" ]; then
				ratio=$(awk -v a="$ltime" -v b="$ptime" 'BEGIN { if (a != "" && b > 0) printf " (lucent / POV-Ray: %.2f)", a / b }')
				echo "<p>Time: lucent ${ltime:-?} s CPU, ${lwall:-?} s wall; POV-Ray ${ptime:-?} s CPU, ${pwall:-?} s wall$ratio.</p>"
			fi
			echo "</section>"
		done < "$tmp/report.order"
		echo "</body></html>"
	} > "$report/index.html"
	echo "Report: $report/index.html"
fi

echo "$npass passed, $nfail failed"
[ "$nfail" -eq 0 ]

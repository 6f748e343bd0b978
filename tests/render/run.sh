#!/bin/sh
# tests/render/run.sh: render every scene of tests/render/*.list with
# lucent, then compare the image
#  (a) with tests/render/expected/NAME.png, exactly: rendering is
#      deterministic, so any changed pixel is a regression (or a deliberate
#      change: then run tests/render/refresh.sh and commit the new images);
#  (b) with POV-Ray 3.7's render tests/render/povray/NAME.png, through
#      OpenImageIO's idiff, within the scene's tolerance. Each line of a
#      list is "NAME WIDTH HEIGHT [IDIFF OPTIONS]"; the options
#      (e.g. -failpercent 0.02) override the default limits below.
# Prints one line per scene with idiff's figures against POV-Ray (mean and
# max error, pixels over the 1/255 threshold) and ends with "N passed,
# M failed". Exit status 77 (skip) if idiff is missing.
# The scenes are listed in tests/render/*.list (one list per area). A line
# may end with "| SWITCHES": render switches (e.g. +A0.1 +AM2) given to both
# lucent and POV-Ray.
: "${top_srcdir:=$(cd "$(dirname "$0")/../.." && pwd)}"

IDIFF=${IDIFF:-idiff}
if ! command -v "$IDIFF" > /dev/null 2>&1; then
	echo "SKIP: idiff (OpenImageIO) not found"
	exit 77
fi

# shellcheck source=tests/lib.sh
. "$top_srcdir/tests/lib.sh"
cd "$top_srcdir" || exit 1
list=$WORK/all.list
cat tests/render/*.list > "$list" || fail "no tests/render/*.list"
# Against POV-Ray: a pixel fails if a channel is off by more than 1/255
# (0.004 > 1/255 = 0.00392), and by default no pixel may fail. The warning
# threshold stays at 1/255 so that the count is always reported.
POV_LIMITS="-fail 0.004 -failpercent 0"
POV_WARN="-warn 0.004 -warnpercent 100"

# figures LOG: "mean M, max X, N px (P%) > 1/255" from idiff -v's output
# (the count over the warning threshold), plus the count over the failure
# threshold when that is another one.
figures() {
	mean=$(sed -n 's/.*Mean error = *\([^ ]*\).*/\1/p' "$1")
	max=$(sed -n 's/.*Max error *= *\([^ ]*\).*/\1/p' "$1")
	# idiff prints the count over the warning threshold, then over the
	# failure threshold: "N pixels (P%) over T".
	counts=$(sed -n 's/^ *\([0-9]*\) pixels (\([^)]*\)) over \([^ ]*\).*/\1 px (\2) > \3/p' "$1")
	c1=$(echo "$counts" | sed -n '1{s|> 0.004$|> 1/255|;p;}')
	c2=$(echo "$counts" | sed -n '2{s|> 0.004$|> 1/255|;p;}')
	[ "$c2" = "$c1" ] && c2=""
	if [ -z "$mean" ]; then
		echo "idiff: $(grep -v '^Comparing' "$1" | tr '\n' ' ')"
	else
		echo "mean $mean, max $max, $c1${c2:+, $c2}"
	fi
}

while read -r name w h opts; do
	case $name in '' | '#'*) continue ;; esac
	sw=""
	case $opts in *'|'*) sw=${opts#*|}; opts=${opts%%|*} ;; esac
	out=$WORK/$name.png
	expected=tests/render/expected/$name.png
	povray=tests/render/povray/$name.png
	# shellcheck disable=SC2086 # the switches are meant to be split
	if ! "$LUCENT" -q +W"$w" +H"$h" $sw scenes/"$name".pov +O"$out" \
			< /dev/null > "$WORK/render.log" 2>&1; then
		fail "$name: lucent failed: $(tr '\n' ' ' < "$WORK/render.log")"
		continue
	fi
	for f in "$expected" "$povray"; do
		[ -f "$f" ] || echo "missing $f (run tests/render/refresh.sh)" > "$WORK/missing"
	done
	if [ -f "$WORK/missing" ]; then
		fail "$name: $(cat "$WORK/missing")"
		rm -f "$WORK/missing"
		continue
	fi
	ok=1
	why=""
	# (a) exactly lucent's stored image.
	if ! "$IDIFF" -v -fail 0 -failpercent 0 -hardfail 0 -warn 0 \
			"$expected" "$out" < /dev/null > "$WORK/exact.log" 2>&1; then
		ok=0
		why="differs from $expected: $(figures "$WORK/exact.log"); "
	fi
	# (b) POV-Ray's render within the tolerance (idiff: 0 pass, 1 warn).
	# shellcheck disable=SC2086 # the options are meant to be split
	"$IDIFF" -v $POV_LIMITS $POV_WARN $opts \
		"$povray" "$out" < /dev/null > "$WORK/pov.log" 2>&1
	rc=$?
	if [ $rc -gt 1 ]; then
		ok=0
		why="${why}too far from POV-Ray ($POV_LIMITS${opts:+ $opts}); "
	fi
	line="$name ${w}x$h: ${why}vs POV-Ray: $(figures "$WORK/pov.log")"
	if [ $ok -eq 1 ]; then pass "$line"; else fail "$line"; fi
done < "$list"
[ $((npass + nfail)) -gt 0 ] || fail "no scene in $list"
finish

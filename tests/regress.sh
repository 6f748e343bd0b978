#!/bin/sh
# tests/regress.sh: lucent-regress itself (tools/lucent-regress.sh), on a
# tiny corpus made here: four scenes, one whose expected image was changed
# (a regression), one whose POV-Ray reference was changed (too far from
# POV-Ray), one whose expected image differs within its "expected:" limits,
# and one unchanged. The "POV-Ray" references are lucent's own renders, so
# the test needs no POV-Ray. Checks the exit status, the order (worst
# first), the totals, the HTML report's figures and images, the list
# format's errors, the parallel run (-j), lucent --regress, and that every
# scene of the project's corpus states in a header comment what it
# exercises.
# shellcheck source=tests/lib.sh
. "${top_srcdir:-.}/tests/lib.sh"
OIIOTOOL=${OIIOTOOL:-oiiotool}
if ! command -v "$OIIOTOOL" > /dev/null 2>&1; then
	echo "SKIP: oiiotool (OpenImageIO) not found"
	exit 77
fi
REGRESS="sh $top_srcdir/tools/lucent-regress.sh"
C=$WORK/corpus
mkdir -p "$C"

# scene NAME COLOUR: a small scene.
scene() {
	cat > "$C/$1.pov" << EOF
// $1.pov: a test scene of tests/regress.sh.
#version 3.7;
camera { location <0, 1, -4> look_at 0 }
light_source { <4, 5, -3> color rgb 1 }
plane { y, -1 pigment { checker color rgb 1 color rgb 0.2 } }
sphere { 0, 1 pigment { color rgb $2 } finish { phong 0.5 } }
EOF
}
scene a-same "<1, 0.5, 0.2>"
scene m-near "<0.2, 0.5, 1>"
scene y-povray "<0.3, 1, 0.3>"
scene z-changed "<1, 1, 0.2>"
cat > "$C/corpus.list" << 'EOF'
# A corpus of tests/regress.sh: NAME WIDTH HEIGHT [LIMITS] [| SWITCHES]
a-same 40 30 -failpercent 1
m-near 40 30 expected: -fail 0.1
y-povray 40 30
z-changed 40 30 | +A0.3 -J
EOF

# The references: lucent's renders, as the expected images and as POV-Ray's.
$REGRESS --refresh=lucent -j 2 "$C/corpus.list" > "$WORK/refresh.log" 2>&1
check "--refresh=lucent exits 0" [ $? -eq 0 ]
check "--refresh=lucent reports each scene" contains "$WORK/refresh.log" "z-changed: 40x30 done"
check "--refresh=lucent writes expected/" [ -f "$C/expected/z-changed.png" ]
mkdir -p "$C/povray"
for n in a-same m-near y-povray z-changed; do
	cp "$C/expected/$n.png" "$C/povray/$n.png"
	echo "0.75 1.5: POV-Ray's CPU time and wall-clock time in seconds" > "$C/povray/$n.time"
done

$REGRESS -j 2 -o "$WORK/report0" "$C/corpus.list" > "$WORK/pass.log" 2>&1
check "unchanged corpus: exit 0" [ $? -eq 0 ]
check "unchanged corpus: 4 passed" [ "$(tail -n 1 "$WORK/pass.log")" = "4 passed, 0 failed" ]
check "unchanged corpus: a figure line per scene" \
	[ "$(grep -c '^PASS: .*vs POV-Ray: mean 0, RMS 0, max 0' "$WORK/pass.log")" -eq 4 ]

# The changes: z-changed's expected image gets a red block (the
# regression), y-povray's POV-Ray image a blue one, m-near's expected image
# is brightened by 0.05 (within its limit of 0.1).
"$OIIOTOOL" "$C/expected/z-changed.png" --fill:color=1,0,0 6x4+10+12 -o "$WORK/z.png" &&
	mv "$WORK/z.png" "$C/expected/z-changed.png"
"$OIIOTOOL" "$C/povray/y-povray.png" --fill:color=0,0,1 4x4+2+2 -o "$WORK/y.png" &&
	mv "$WORK/y.png" "$C/povray/y-povray.png"
"$OIIOTOOL" "$C/expected/m-near.png" --addc 0.05 -o "$WORK/m.png" &&
	mv "$WORK/m.png" "$C/expected/m-near.png"

R=$WORK/report
$REGRESS -j 2 -o "$R" "$C/corpus.list" > "$WORK/run.log" 2>&1
rc=$?
sed 's/^/  | /' "$WORK/run.log"
check "a regression: exit status 1" [ $rc -eq 1 ]
grep -E '^(PASS|FAIL): ' "$WORK/run.log" | cut -d' ' -f1,2 > "$WORK/order"
printf '%s\n' "FAIL: z-changed" "FAIL: y-povray" "PASS: m-near" "PASS: a-same" > "$WORK/order.want"
check "worst first: the regression, the POV-Ray failure, then the passes by error" \
	cmp -s "$WORK/order" "$WORK/order.want"
check "the regression says what differs" \
	contains "$WORK/run.log" "FAIL: z-changed 40x30: differs from $C/expected/z-changed.png: mean"
check "the POV-Ray failure names the limits" \
	contains "$WORK/run.log" "FAIL: y-povray 40x30: too far from POV-Ray (-fail 0.004 -failpercent 0): mean"
# 16 of 1200 pixels changed: 1.33%.
check "the count of pixels over 1/255" contains "$WORK/run.log" "16 px (1.33%) > 1/255"
check "within the expected: limits" contains "$WORK/run.log" "PASS: m-near 40x30: within limits of"
check "POV-Ray's time from its .time file" contains "$WORK/run.log" "POV-Ray 0.75 s"
check "the totals" contains "$WORK/run.log" "Totals: 4 scenes, 2 passed, 2 failed"
check "the last line" [ "$(tail -n 1 "$WORK/run.log")" = "2 passed, 2 failed" ]

# The report: the scene's section first, with the figures of the terminal.
check "the report exists" [ -f "$R/index.html" ]
first=$(sed -n 's/^<section id="\([^"]*\)">.*/\1/p' "$R/index.html" | head -n 1)
check "the report lists the regression first" [ "$first" = z-changed ]
sed -n '/<section id="z-changed">/,/<\/section>/p' "$R/index.html" > "$WORK/z.html"
for fig in mean max; do
	v=$(grep '^FAIL: z-changed' "$WORK/run.log" | cut -d';' -f1 | sed -n "s/.* $fig \\([^,]*\\),.*/\\1/p")
	check "the report has the regression's $fig error ($v)" \
		grep -q "<td>$v</td>\\|<td>$v at" "$WORK/z.html"
done
check "the report has the PSNR column" contains "$WORK/z.html" "PSNR (dB)"
check "the report's index links to the scene first" \
	[ "$(grep -o 'href="#[^"]*"' "$R/index.html" | head -n 1)" = 'href="#z-changed"' ]
check "the report has the changed pixels" contains "$WORK/z.html" "24 px (2%) &gt; 0"
check "the report has both times" contains "$WORK/z.html" "POV-Ray 0.75 s CPU, 1.5 s wall"
check "the report marks it failed" contains "$WORK/z.html" '<td class="FAIL">FAIL</td>'
for img in z-changed z-changed-povray z-changed-diff z-changed-expected z-changed-expdiff; do
	check "the report has images/$img.png" [ -f "$R/images/$img.png" ]
	check "the report shows images/$img.png" contains "$WORK/z.html" "src=\"images/$img.png\""
done
# The heat map of the regression: (nearly) black where the images agree,
# bright in the changed block.
# maxof X Y: the largest channel value (0..1) of the heat map's pixel.
maxof() {
	"$OIIOTOOL" "$R/images/z-changed-expdiff.png" --cut "1x1+$1+$2" --printstats 2>&1 |
		awk '/Stats Max:/ { m = $3; if ($4 > m) m = $4; if ($5 > m) m = $5; print m }'
}
v=$(maxof 0 0)
check "the heat map is dark where the images agree ($v)" awk -v v="${v:-1}" 'BEGIN { exit !(v < 0.03) }'
v=$(maxof 12 13)
check "the heat map is bright where they differ ($v)" awk -v v="${v:-0}" 'BEGIN { exit !(v > 0.8) }'

# -n selects scenes; -q prints only the failures; options may follow the
# operands.
$REGRESS -q -n 'a-*' "$C/corpus.list" -n m-near --no-report > "$WORK/sel.log" 2>&1
check "-n selects: exit 0" [ $? -eq 0 ]
check "-n selects: 2 passed" [ "$(tail -n 1 "$WORK/sel.log")" = "2 passed, 0 failed" ]
check "-q prints no PASS line" [ "$(grep -c '^PASS' "$WORK/sel.log")" -eq 0 ]

# Errors of the list format: file:line and exit status 2.
echo "bad 40" > "$C/bad.list"
$REGRESS --no-report "$C/bad.list" > "$WORK/bad.log" 2>&1
check "a short line: exit 2" [ $? -eq 2 ]
check "a short line: file:line" contains "$WORK/bad.log" "$C/bad.list:1: expected NAME WIDTH HEIGHT"
echo "a-same 40 30 -pixels 3" > "$C/bad.list"
$REGRESS --no-report "$C/bad.list" > "$WORK/bad.log" 2>&1
check "an unknown limit: exit 2" [ $? -eq 2 ]
check "an unknown limit: named" contains "$WORK/bad.log" "$C/bad.list:1: unknown limit '-pixels'"
$REGRESS --no-report -n nothing "$C/corpus.list" > "$WORK/bad.log" 2>&1
check "-n matching nothing: exit 2" [ $? -eq 2 ]
echo "a-same 40 30" > "$C/bad.list"
$REGRESS --no-report "$C/corpus.list" "$C/bad.list" > "$WORK/bad.log" 2>&1
check "a scene listed twice: exit 2" [ $? -eq 2 ]
check "a scene listed twice: named" contains "$WORK/bad.log" "listed more than once: a-same"

# A folder of scenes without a list: its *.pov at 160x120, with the
# references in its expected/ and povray/ folders (none here: missing).
mkdir -p "$WORK/plain"
cp "$C/a-same.pov" "$WORK/plain/"
$REGRESS --no-report "$WORK/plain" > "$WORK/plain.log" 2>&1
check "a folder without references: exit 1" [ $? -eq 1 ]
check "a folder without references: says so" contains "$WORK/plain.log" "FAIL: a-same 160x120: missing"

# lucent --regress runs the lucent-regress beside it.
if [ -x "$(dirname "$LUCENT")/lucent-regress" ]; then
	"$LUCENT" --regress --no-report -n a-same "$C/corpus.list" > "$WORK/fwd.log" 2>&1
	check "lucent --regress: exit 0" [ $? -eq 0 ]
	check "lucent --regress: runs lucent-regress" contains "$WORK/fwd.log" "1 passed, 0 failed"
fi

# The project's corpus: every scene says in a header comment what it
# exercises (its first line is a // comment of some length).
ok=1
for f in "$top_srcdir"/scenes/*.pov; do
	first=$(head -n 1 "$f")
	case $first in
	'// '??????????*) ;;
	*) fail "$(basename "$f"): no header comment saying what the scene exercises"; ok=0 ;;
	esac
done
[ $ok -eq 1 ] && pass "every scene of scenes/ has a header comment"
# ... and is rendered by a line of tests/render/*.list.
ok=1
for f in "$top_srcdir"/scenes/*.pov; do
	n=$(basename "$f" .pov)
	if ! grep -q "^$n " "$top_srcdir"/tests/render/*.list; then
		fail "$n.pov: in no tests/render/*.list"
		ok=0
	fi
done
[ $ok -eq 1 ] && pass "every scene of scenes/ is in a list"

finish

#!/bin/sh
# tests/determinism.sh: the same scene and switches give bit-identical
# files whatever +WT is, and a render split by +SR/+ER (or +SC/+EC) has
# exactly the pixels of the whole render.
. "${top_srcdir:-.}/tests/lib.sh"
scene="$top_srcdir/scenes/showcase.pov"
W=160
H=120
r() { "$LUCENT" -q +W$W +H$H "$scene" "$@"; }

r +WT1 +O"$WORK/t1.png" && r +WT2 +O"$WORK/t2.png" && r +WT7 +O"$WORK/t7.png"
check "+WT1 and +WT2 give identical files" cmp -s "$WORK/t1.png" "$WORK/t2.png"
check "+WT1 and +WT7 give identical files" cmp -s "$WORK/t1.png" "$WORK/t7.png"

# Antialiasing with jitter: every jitter offset is a hash of the sample's
# coordinates, so threads and tile order cannot change a pixel. Method 1
# compares neighbours across tile borders; method 2 shares corner samples
# between pixels.
differ() { ! cmp -s "$1" "$2"; }
for m in "+AM1 +R3" "+AM2 +R3"; do
	# shellcheck disable=SC2086 # the switches are meant to be split
	r +A0.1 $m +J +WT1 +O"$WORK/j1.png" && r +A0.1 $m +J +WT2 +O"$WORK/j2.png" &&
		r +A0.1 $m +J +WT7 +O"$WORK/j7.png" && r +A0.1 $m -J +WT2 +O"$WORK/nj.png"
	check "jittered $m: +WT1 and +WT2 give identical files" cmp -s "$WORK/j1.png" "$WORK/j2.png"
	check "jittered $m: +WT1 and +WT7 give identical files" cmp -s "$WORK/j1.png" "$WORK/j7.png"
	check "jittered $m: the jitter changes the image" differ "$WORK/j1.png" "$WORK/nj.png"
done

# Rows: 1-37 and 38-120 by pixel number; the halves by fraction.
r +SR1 +ER37 +O"$WORK/top.png" && r +SR38 +ER120 +O"$WORK/bottom.png"
oiiotool "$WORK/top.png" "$WORK/bottom.png" --add -o "$WORK/rows.png"
check "rows split by pixel number add up to the whole image" \
	idiff -fail 0 -failpercent 0 -warn 0 "$WORK/t1.png" "$WORK/rows.png"
r +SR0 +ER0.5 +O"$WORK/h1.png" && r +SR0.5 +ER1.0 +O"$WORK/h2.png"
oiiotool "$WORK/h1.png" "$WORK/h2.png" --add -o "$WORK/halves.png"
check "rows split by fraction add up to the whole image" \
	idiff -fail 0 -failpercent 0 -warn 0 "$WORK/t1.png" "$WORK/halves.png"
r +SC1 +EC50 +O"$WORK/left.png" && r +SC51 +EC160 +O"$WORK/right.png"
oiiotool "$WORK/left.png" "$WORK/right.png" --add -o "$WORK/cols.png"
check "columns split by pixel number add up to the whole image" \
	idiff -fail 0 -failpercent 0 -warn 0 "$WORK/t1.png" "$WORK/cols.png"
# A partial render is the full size, black outside the region (as POV-Ray).
iinfo "$WORK/top.png" > "$WORK/info.txt"
check "a partial render keeps the full image size" grep -qE "160 x +120" "$WORK/info.txt"
oiiotool "$WORK/top.png" --cut 160x83+0+37 --printstats > "$WORK/stats.txt" 2>&1
check "outside the region is black" grep -qE "Stats Max: 0(\.0+)? 0(\.0+)? 0(\.0+)? " "$WORK/stats.txt"
# --- cameras: focal blur (lens samples hashed per pixel) ---
blur="$top_srcdir/scenes/cam-focal-adaptive.pov"
"$LUCENT" -q +W80 +H60 "$blur" +WT1 +O"$WORK/fb1.png" &&
	"$LUCENT" -q +W80 +H60 "$blur" +WT2 +O"$WORK/fb2.png"
check "focal blur: +WT1 and +WT2 give identical files" cmp -s "$WORK/fb1.png" "$WORK/fb2.png"
bokeh="$top_srcdir/scenes/cam-bokeh.pov"
"$LUCENT" -q +W80 +H60 "$bokeh" +WT1 +O"$WORK/bk1.png" &&
	"$LUCENT" -q +W80 +H60 "$bokeh" +WT2 +O"$WORK/bk2.png"
check "focal blur with a bokeh: +WT1 and +WT2 give identical files" cmp -s "$WORK/bk1.png" "$WORK/bk2.png"
# --- end cameras ---
finish

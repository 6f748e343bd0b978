#!/bin/sh
# tests/reliability.sh: bad or hostile scenes within bounds (issue 9;
# doc/reliability.md): Ctrl-C while parsing an endless loop, the file rule
# for #include, #fopen and image maps (what is allowed, and the switches
# that widen it), and output images that survive a render stopped at
# random points. The refusals are in tests/errors/fuzz-*.pov.
. "${top_srcdir:-.}/tests/lib.sh"
cd "$WORK" || exit 1

# ---- Ctrl-C while parsing ----
# interrupted SIGNAL NAME: renders NAME.pov in the background, sends it
# SIGNAL half a second later and sets rc to its exit status. A watchdog
# kills it after 30 s, so that a parse deaf to the signal fails the test
# rather than hangs it.
interrupted() {
	"$LUCENT" -q +W8 +H6 "$2.pov" +O"$2.png" > err.txt 2>&1 &
	pid=$!
	sleep 0.5
	kill -"$1" $pid
	( sleep 30; kill -KILL $pid 2>/dev/null ) &
	dog=$!
	wait $pid
	rc=$?
	kill $dog 2>/dev/null
}

cat > loop.pov <<'POV'
#declare I = 0;
#while (1)
  #declare I = I + 1;
#end
POV
interrupted INT loop
check "Ctrl-C in an endless #while exits with status 2" [ $rc -eq 2 ]
check "Ctrl-C names the loop and where it was" grep -qE '^loop\.pov:[234]:[0-9]+: error: interrupted while parsing, in the #while loop at loop\.pov:2$' err.txt
check "Ctrl-C while parsing writes no image" [ ! -f loop.png ]

cat > forloop.pov <<'POV'
#macro Work(X) #local Y = X * 2; #end
#for (I, 0, 1e12)
  Work(I)
#end
POV
interrupted TERM forloop
check "SIGTERM in a #for with macro calls exits with status 2" [ $rc -eq 2 ]
check "the message names the #for loop" grep -qE '^forloop\.pov:[0-9]+:[0-9]+: error: interrupted while parsing, in the #for loop at forloop\.pov:2$' err.txt

# A function's sum() over 1e15 terms (fuzz run 12's hang): POV-Ray loops as
# long, but Ctrl-C must stop it.
cat > sum.pov <<'POV'
#declare F = function(n) { sum(i, 1, n, i * i) }
#declare X = F(1e15);
POV
interrupted INT sum
check "Ctrl-C in a long sum() while parsing exits with status 2" [ $rc -eq 2 ]
check "the message says where the parser was" grep -qE '^sum\.pov:[0-9]+:[0-9]+: error: interrupted while parsing' err.txt

# Focal blur with blur_samples 2e9 and variance 0: each pixel takes its 2e9
# samples, hours (POV-Ray too); the render looks at its stop flag between
# tiles, so the lens loop must look at it as well.
cat > blur.pov <<'POV'
camera { location -5*z look_at 0 aperture 1 focal_point 0 blur_samples 2000000000 variance 0 }
sphere { 0, 1 pigment { rgb 1 } }
light_source { <1, 2, -3> rgb 1 }
POV
interrupted INT blur
check "Ctrl-C inside a pixel of 2e9 blur samples exits with status 2" [ $rc -eq 2 ]
check "the message says no image was written" grep -q 'interrupted; no image written' err.txt
check "and none was" [ ! -f blur.png ]

# ---- #write ----
# #fclose among #write's arguments (fuzz run 16: a use after free of the
# file being written): an error, and what came before it written.
cat > wclose.pov <<'POV'
#fopen F "wclose.txt" write
#write (F, "a", 1 + 0
#fclose F
, "b")
POV
"$LUCENT" -q +W8 +H6 -F wclose.pov > err.txt 2>&1
rc=$?
check "#fclose among #write's arguments is an error (status 1)" [ $rc -eq 1 ]
check "it says the file was closed" grep -qE "^wclose\.pov:4:6: error: #write's file was closed among its arguments$" err.txt
check "what #write had before is in the file" [ "$(cat wclose.txt)" = a1 ]

# Binary words are rounded (floor(x + 0.5)) and held to the word's range;
# a float past a long long's range was cast as it was (fuzz run 21, UBSan).
# The bytes are POV-Ray 3.7's for the same #write.
cat > words.pov <<'POV'
#fopen F "words.bin" write
#write (F, uint8 300, sint8 -200, uint16le 70000, sint16be -40000, uint8 3.7, uint8 -1.5, sint32le 3e9)
#write (F, uint8 2.5, uint8 255.6, sint8 -128.7, sint8 -2.5, sint8 -2.6, uint8 -0.6, sint16le 1e300, uint8 -1e93)
#fclose F
POV
"$LUCENT" -q +W8 +H6 -F words.pov > err.txt 2>&1
rc=$?
check "binary #write of out-of-range words (status 0)" [ $rc -eq 0 ]
check "the words are rounded and clamped as POV-Ray writes them" \
	[ "$(od -An -tx1 words.bin | tr -d ' \n')" = ff80ffff80000400ffffff7f03ff80fefd00ff7f00 ]

# ---- the file rule: what is allowed ----
mkdir -p scene/sub lib
echo '#declare FromSub = 1;' > scene/sub/a.inc
echo '#declare FromLib = 2;' > lib/b.inc
cat > scene/ok.pov <<'POV'
#include "sub/a.inc"
#include "sub/../sub/a.inc"
#fopen Out "sub/written.txt" write
#write (Out, "3,\n")
#fclose Out
#fopen In "sub/written.txt" read
#read (In, V)
#if (FromSub != 1 | V != 3) #error "wrong values" #end
POV
"$LUCENT" -q +W8 +H6 -F scene/ok.pov > err.txt 2>&1
check "the scene's folder and its subfolders can be read and written" [ $? -eq 0 ]
printf '#include "../lib/b.inc"\n#if (FromLib != 2) #error "wrong" #end\n' > scene/lib.pov
"$LUCENT" -q +W8 +H6 -F scene/lib.pov > err.txt 2>&1
check "a file outside the scene's folder is refused" contains err.txt 'may not read "../lib/b.inc"'
"$LUCENT" -q +W8 +H6 -F +L"$WORK/lib" scene/lib.pov > err.txt 2>&1
check "+L makes a folder readable" [ $? -eq 0 ]
printf '#include "b.inc"\n' > scene/libsearch.pov
"$LUCENT" -q +W8 +H6 -F +Llib scene/libsearch.pov > err.txt 2>&1
check "a file found through a relative +L path is readable" [ $? -eq 0 ]
"$LUCENT" -q +W8 +H6 -F --io-unrestricted scene/lib.pov > err.txt 2>&1
check "--io-unrestricted lifts the rule for reading" [ $? -eq 0 ]
printf '#fopen O "../lib/out.txt" write\n#write (O, "1")\n#fclose O\n' > scene/wr.pov
"$LUCENT" -q +W8 +H6 -F +L"$WORK/lib" scene/wr.pov > err.txt 2>&1
check "+L does not make a folder writable" contains err.txt 'may not write "../lib/out.txt"'
check "... and nothing was written" [ ! -f lib/out.txt ]
"$LUCENT" -q +W8 +H6 -F --io-unrestricted scene/wr.pov > err.txt 2>&1
check "--io-unrestricted lifts the rule for writing" [ -f lib/out.txt ]
ln -s "$WORK/lib/b.inc" scene/link.inc
printf '#include "link.inc"\n' > scene/link.pov
"$LUCENT" -q +W8 +H6 -F scene/link.pov > err.txt 2>&1
check "a symbolic link out of the scene's folder is refused" contains err.txt 'may not read "link.inc"'
printf '#include "colors.inc"\n#declare C = Red;\n' > scene/std.pov
"$LUCENT" -q +W8 +H6 -F scene/std.pov > err.txt 2>&1
check "the stdlib is readable" [ $? -eq 0 ]

# ---- limits: named in the error, raised with --limit ----
printf '#declare S = "abcdefgh";\n#while (1)\n  #declare S = concat(S, S);\n#end\n' > grow.pov
"$LUCENT" -q +W8 +H6 -F --limit string-length=1000 grow.pov > err.txt 2>&1
rc=$?
check "a string past its limit is an error (status 1)" [ $rc -eq 1 ]
check "... that names the limit and the option" contains err.txt "concat() would make a string longer than 1000 bytes (lucent --limit string-length=N raises the limit)"
printf '#declare A = array[2000][1000];\n' > arr.pov
"$LUCENT" -q +W8 +H6 -F --limit array-size=1000 arr.pov > err.txt 2>&1
check "--limit array-size lowers the array limit" contains err.txt "more than 1000 elements (lucent --limit array-size=N"
"$LUCENT" -q +W8 +H6 -F --limit array-size=2000000 arr.pov > err.txt 2>&1
check "--limit array-size raises it" [ $? -eq 0 ]
printf '#macro R(N) #if (N > 0) R(N - 1) #end #end\nR(1500)\n' > deep.pov
"$LUCENT" -q +W8 +H6 -F deep.pov > err.txt 2>&1
check "1500 nested macro calls pass the default limit (1000) only when raised" contains err.txt "(lucent --limit macro-depth=N raises the limit)"
"$LUCENT" -q +W8 +H6 -F --limit macro-depth=2000 deep.pov > err.txt 2>&1
check "--limit macro-depth=2000 lets them run" [ $? -eq 0 ]
"$LUCENT" -q +W8 +H6 -F --limit nonsense=3 deep.pov > err.txt 2>&1
check "an unknown limit is refused, naming the known ones" contains err.txt "unknown limit 'nonsense' (macro-depth"
"$LUCENT" -q +W20000 +H20000 deep.pov > err.txt 2>&1
check "an image over the size limit fails before parsing" contains err.txt "a 20000x20000 image has more than 100000000 pixels (lucent --limit image-size=N raises the limit)"
# 65536x65536 float RGBA is 64 GiB: more than the machines this runs on.
"$LUCENT" -q +W65536 +H65536 --limit image-size=1e10 deep.pov > err.txt 2>&1
rc=$?
check "an image larger than the machine's memory fails with a clear error" [ $rc -eq 1 ]
check "... saying so" contains err.txt "needs more memory than the machine has"

# ---- output: a stopped render leaves the previous image intact ----
cat > slow.pov <<'POV'
#version 3.7;
camera { location <0, 1, -4> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
#for (I, 0, 40)
  sphere { <mod(I, 7) - 3, div(I, 7) - 2, 0>, 0.45 pigment { granite } finish { reflection 0.3 } }
#end
plane { y, -3 pigment { checker } finish { reflection 0.5 } }
POV
"$LUCENT" -q +W64 +H48 slow.pov +Oout.png > err.txt 2>&1
cp out.png before.png
intact=1
leftover=0
for delay in 0.05 0.1 0.2 0.3 0.4 0.6 0.8 1.0 1.3 1.6; do
	"$LUCENT" -q +W320 +H240 +A0.1 +WT1 slow.pov +Oout.png > err.txt 2>&1 &
	pid=$!
	sleep $delay
	kill -INT $pid 2>/dev/null
	wait $pid
	rc=$?
	# Stopped: the old image; finished before the signal: a new, whole one.
	if [ $rc -eq 2 ]; then
		cmp -s out.png before.png || intact=0
	elif [ $rc -eq 0 ]; then
		iinfo out.png 2>/dev/null | grep -qE "320 x +240" || intact=0
		cp before.png out.png
	else
		intact=0
	fi
	ls -a | grep -q '\.tmp' && leftover=1
done
check "a render stopped at random points leaves the previous image intact" [ $intact -eq 1 ]
check "... and no temporary file behind" [ $leftover -eq 0 ]

finish

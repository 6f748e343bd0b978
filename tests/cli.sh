#!/bin/sh
# tests/cli.sh: the lucent command itself: --version, --help, output naming,
# formats, exit statuses, error messages for bad options and missing files,
# and that a failed or interrupted render never clobbers an existing image.
. "${top_srcdir:-.}/tests/lib.sh"
cd "$WORK" || exit 1

cat > ok.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
sphere { 0, 1 pigment { color rgb <1, 0.5, 0.2> } }
POV

# --version and --help
"$LUCENT" --version > out.txt 2>&1; rc=$?
check "--version exits 0" [ $rc -eq 0 ]
check "--version prints the version" grep -qE '^lucent [0-9]+\.[0-9]+\.[0-9]+$' out.txt
"$LUCENT" --help > out.txt 2>&1; rc=$?
check "--help exits 0" [ $rc -eq 0 ]
check "--help lists +W" contains out.txt "+Wn"
check "--help lists --threads" contains out.txt "--threads"

# Default output name: the scene's name with .png, beside it.
mkdir -p sub
cp ok.pov sub/scene.pov
"$LUCENT" -q +W16 +H12 sub/scene.pov > out.txt 2>&1; rc=$?
check "render exits 0" [ $rc -eq 0 ]
check "scene.pov renders scene.png beside it" [ -f sub/scene.png ]
check "-q prints nothing for a clean scene" [ ! -s out.txt ]
iinfo sub/scene.png > info.txt 2>&1
check "default output is 16x12 8-bit PNG" grep -qE "16 x +12, 3 channel, uint8 png" info.txt

# +O and the formats
"$LUCENT" -q +W16 +H12 +Iok.pov +Oa.exr && iinfo a.exr > info.txt 2>&1
check "+O with .exr writes OpenEXR" grep -q "openexr" info.txt
"$LUCENT" -q +W16 +H12 ok.pov +FN16 +Ob16.png && iinfo b16.png > info.txt 2>&1
check "+FN16 writes 16-bit PNG" grep -q "uint16 png" info.txt
"$LUCENT" -q +W16 +H12 ok.pov +UA +Oalpha.png && iinfo alpha.png > info.txt 2>&1
check "+UA writes an alpha channel" grep -q "4 channel" info.txt
oiiotool alpha.png --ch A --printstats > stats.txt 2>&1
check "+UA makes the background transparent" grep -qE "Stats Min: 0(\.0+)? " stats.txt
check "+UA keeps objects opaque" grep -qE "Stats Max: 1(\.0+)? " stats.txt
"$LUCENT" -q +W16 +H12 ok.pov +Onoext && [ -f noext.png ]
check "+O without an extension gets the format's" [ $? -eq 0 ]
"$LUCENT" -q +W16 +H12 ok.pov +Oimg.bmp > err.txt 2>&1; rc=$?
check "an unknown image extension exits 1" [ $rc -eq 1 ]
check "an unknown image extension is named" contains err.txt "unknown image type '.bmp'"
"$LUCENT" -q +W16 +H12 ok.pov +FT +Ot.tga && iinfo t.tga > info.txt 2>&1
check "+FT writes TGA" grep -q "targa" info.txt
"$LUCENT" -q +W16 +H12 ok.pov +Ot.tif && iinfo t.tif > info.txt 2>&1
check ".tif writes TIFF" grep -q "tiff" info.txt
"$LUCENT" -q +W16 +H12 ok.pov +FP +Op.ppm && iinfo p.ppm > info.txt 2>&1
check "+FP writes PPM" grep -q "pnm" info.txt
"$LUCENT" -q +W16 +H12 ok.pov +FJ +Oj.jpg && iinfo j.jpg > info.txt 2>&1
check "+FJ writes JPEG" grep -q "jpeg" info.txt
"$LUCENT" -q +W16 +H12 ok.pov +FH +Oh.hdr && iinfo h.hdr > info.txt 2>&1
check "+FH writes HDR" grep -q "hdr" info.txt
"$LUCENT" -q +W16 +H12 ok.pov --output long.png && [ -f long.png ]
check "--output FILE" [ $? -eq 0 ]
rm -f nofile.png
"$LUCENT" -q +W16 +H12 ok.pov -F +Onofile.png
check "-F writes no file" [ ! -f nofile.png ]

# +V says what is being rendered.
"$LUCENT" +V -F +W16 +H12 ok.pov > out.txt 2>&1
check "+V reports objects, lights and threads" grep -q "1 objects (0 unbounded), 1 lights" out.txt
check "statistics report rays by kind" grep -qE "^    camera +192$" out.txt
check "statistics report skipped effects" grep -q "skipped .*reflection" out.txt

# Gamma: a 3.7 scene with assumed_gamma 1 is sRGB-encoded (0.5 -> 188);
# a scene without #version gets no gamma handling (0.5 -> 128), as POV-Ray.
printf '#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\nbackground { rgb 0.5 }\n' > g37.pov
printf 'background { rgb 0.5 }\n' > gold.pov
"$LUCENT" -q +W4 +H4 g37.pov && oiiotool g37.png --printstats > stats.txt 2>&1
check "assumed_gamma 1.0 encodes 0.5 as sRGB 188" grep -qE "Stats Avg: 188(\.0+)? " stats.txt
"$LUCENT" -q +W4 +H4 gold.pov && oiiotool gold.png --printstats > stats.txt 2>&1
check "no #version: 0.5 is written as 128" grep -qE "Stats Avg: 128(\.0+)? " stats.txt

# #fopen stays in the scene's folder unless --io-unrestricted.
mkdir -p io/sub
printf '#version 3.7;\n#fopen F "../escaped.txt" write\n#write (F, "x")\n#fclose F\n' > io/sub/esc.pov
"$LUCENT" -q -F io/sub/esc.pov > err.txt 2>&1; rc=$?
check "#fopen outside the scene's folder exits 1" [ $rc -eq 1 -a ! -f io/escaped.txt ]
check "#fopen outside the scene's folder names the switch" contains err.txt "--io-unrestricted"
"$LUCENT" -q -F --io-unrestricted io/sub/esc.pov > err.txt 2>&1; rc=$?
check "--io-unrestricted lets #fopen leave the folder" [ $rc -eq 0 -a -f io/escaped.txt ]

# Standard input
"$LUCENT" -q +W16 +H12 - +Ostdin.png < ok.pov; rc=$?
check "'-' reads the scene from standard input" [ $rc -eq 0 -a -f stdin.png ]

# .ini files and Declare
cat > r.ini <<'INI'
; a POV-Ray style ini file
[defaults]
Width=24
Height=18
Output_File_Name=ini.png
Declare=R=0.5
INI
cat > decl.pov <<'POV'
#version 3.7;
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
sphere { 0, R pigment { color rgb 1 } }
POV
"$LUCENT" -q r.ini decl.pov; rc=$?
iinfo ini.png > info.txt 2>&1
check "ini file sets size, output and Declare" grep -qE "24 x +18" info.txt

# Errors: exit status 1 and a message naming the problem.
"$LUCENT" -q missing.pov > err.txt 2>&1; rc=$?
check "missing scene exits 1" [ $rc -eq 1 ]
check "missing scene is named" contains err.txt "cannot read scene file 'missing.pov'"
"$LUCENT" -q ok.pov +Zzz > err.txt 2>&1; rc=$?
check "unknown switch exits 1" [ $rc -eq 1 ]
check "unknown switch is named" contains err.txt "unknown switch '+Zzz'"
"$LUCENT" -q ok.pov --frobnicate > err.txt 2>&1; rc=$?
check "unknown long option exits 1" [ $rc -eq 1 ]
check "unknown long option is named" contains err.txt "unknown option '--frobnicate'"
"$LUCENT" -q ok.pov +Wabc > err.txt 2>&1; rc=$?
check "bad width exits 1" [ $rc -eq 1 ]
check "bad width is explained" contains err.txt "bad value in '+Wabc'"
"$LUCENT" > err.txt 2>&1; rc=$?
check "no scene exits 1" [ $rc -eq 1 ]
check "no scene is explained" contains err.txt "no scene file given"
"$LUCENT" -q +W16 +H12 ok.pov +UR +Oaa.png > err.txt 2>&1; rc=$?
check "unimplemented switch still renders" [ $rc -eq 0 -a -f aa.png ]
check "unimplemented switch is reported by name" contains err.txt "switch '+UR' (remove bounds) is not implemented yet"

# Antialiasing and quality switches: accepted values render, bad ones are
# errors naming the switch (POV-Ray clamps or refuses them silently).
"$LUCENT" -q +W16 +H12 ok.pov +A0.3 +AM2 +R4 +J0.5 +AG2.2 +Q5 -F > err.txt 2>&1; rc=$?
check "+A0.3 +AM2 +R4 +J0.5 +AG2.2 +Q5 render quietly" [ $rc -eq 0 -a ! -s err.txt ]
"$LUCENT" -q +W16 +H12 ok.pov +A -A0.2 -J +J -J0.3 +Q0 +Q11 +R1 +R9 +AM1 -F > err.txt 2>&1; rc=$?
check "switch forms with and without values are accepted" [ $rc -eq 0 -a ! -s err.txt ]
for bad in "+A3.5:antialiasing threshold must be from 0 to 3" "+Aabc:antialiasing threshold must be from 0 to 3" \
	"+A-0.1:antialiasing threshold must be from 0 to 3" "+AM3:sampling method is 1 or 2" "+AM0:sampling method is 1 or 2" \
	"+R0:antialiasing depth is a whole number from 1 to 9" "+R10:antialiasing depth is a whole number from 1 to 9" \
	"+R2.5:antialiasing depth is a whole number from 1 to 9" "+R:antialiasing depth is a whole number from 1 to 9" \
	"+J2:jitter amount must be from 0 to 1" "+J-1:jitter amount must be from 0 to 1" \
	"+AG0:antialiasing gamma must be above 0" "+AGx:antialiasing gamma must be above 0" "+Q12:quality is a whole number from 0 to 11" \
	"+Q-1:quality is a whole number from 0 to 11" "+Q:quality is a whole number from 0 to 11" \
	"+Q4.5:quality is a whole number from 0 to 11"; do
	sw=${bad%%:*}
	"$LUCENT" -q +W16 +H12 ok.pov "$sw" -F > err.txt 2>&1; rc=$?
	check "$sw exits 1" [ $rc -eq 1 ]
	check "$sw is explained" contains err.txt "bad value in '$sw': the ${bad#*:}"
done
cat > aa.ini <<'INI'
Antialias=on
Antialias_Threshold=0.1
Sampling_Method=2
Antialias_Depth=2
Jitter=off
Jitter_Amount=0.5
Antialias_Gamma=1.0
Quality=8
INI
"$LUCENT" +W16 +H12 aa.ini ok.pov -F > out.txt 2>&1; rc=$?
check "ini antialiasing and quality keys are read" [ $rc -eq 0 ]
check "Antialias=on turns antialiasing on" grep -q "simulated .*antialiasing" out.txt
check "Sampling_Method=2 +R2: corner samples (5x5 grid points of a 4x4 tile, and more)" \
	grep -qE "^  samples +[0-9]+ \(([2-9]|[1-9][0-9])\.[0-9]+ per pixel\)" out.txt
printf 'Antialias_Threshold=0.1\n' > thr.ini
"$LUCENT" +W16 +H12 thr.ini ok.pov -F > out.txt 2>&1
check "Antialias_Threshold alone does not turn antialiasing on" grep -qE "^  samples +192 " out.txt
printf 'Antialias_Depth=12\n' > bad.ini
"$LUCENT" -q +W16 +H12 bad.ini ok.pov -F > err.txt 2>&1; rc=$?
check "a bad Antialias_Depth in an ini file exits 1" [ $rc -eq 1 ]
check "a bad Antialias_Depth names the file and line" contains err.txt "bad.ini:1: error: bad value in '+R12'"
printf 'Jitter=maybe\n' > bad.ini
"$LUCENT" -q +W16 +H12 bad.ini ok.pov -F > err.txt 2>&1; rc=$?
check "Jitter=maybe is refused" contains err.txt "Jitter wants on or off, not 'maybe'"
"$LUCENT" +W16 +H12 +Q3 ok.pov -F > out.txt 2>&1
check "+Q3 leaves out shadows, and says so" grep -q "left out .*shadows (quality +Q3)" out.txt
"$LUCENT" -q ok.pov +SR0.9 +ER0.2 > err.txt 2>&1; rc=$?
check "empty partial region exits 1" [ $rc -eq 1 ]

# A failed render never clobbers an existing image, and leaves no temp file.
cp sub/scene.png keep.png
cp keep.png victim.png
printf 'sphere { <0,0,0>, 1\n' > broken.pov
"$LUCENT" -q broken.pov +Ovictim.png > err.txt 2>&1; rc=$?
check "syntax error exits 1" [ $rc -eq 1 ]
check "syntax error keeps the old image" cmp -s keep.png victim.png
check "no temporary file is left" [ -z "$(ls -A | grep '\.tmp')" ]
mkdir ro && chmod 555 ro
if [ "$(id -u)" != 0 ]; then
	"$LUCENT" -q +W16 +H12 ok.pov +Oro/x.png > err.txt 2>&1; rc=$?
	check "unwritable folder exits 1" [ $rc -eq 1 ]
fi

# Interrupting a render: exit 2, the old image intact, no temporary file.
cat > slow.pov <<'POV'
#version 3.7;
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
sphere { 0, 1 pigment { color rgb 1 } finish { reflection 0.9 } }
sphere { <0, 0, -4>, 0.5 pigment { color rgb 1 } finish { reflection 0.9 } }
plane { y, -1 pigment { color rgb 0.5 } finish { reflection 0.5 } }
POV
cp keep.png victim.png
"$LUCENT" -q +W6000 +H6000 +WT1 slow.pov +Ovictim.png > err.txt 2>&1 &
pid=$!
sleep 0.5
kill -INT $pid
wait $pid; rc=$?
check "SIGINT exits 2" [ $rc -eq 2 ]
check "SIGINT keeps the old image" cmp -s keep.png victim.png
check "SIGINT leaves no temporary file" [ -z "$(ls -A | grep '\.tmp')" ]
check "SIGINT says so" contains err.txt "interrupted"

# --signature: one flat colour per primitive (CSG leaves included), no
# lighting, the same image every time (tests/cli-signature.png).
"$LUCENT" +W80 +H60 --signature "$top_srcdir/scenes/csg-ops.pov" +Osig.png > err.txt 2>&1; rc=$?
check "--signature renders" [ $rc -eq 0 ]
check "--signature gives the stored image" idiff -fail 0 -failpercent 0 -hardfail 0 \
	"$top_srcdir/tests/cli-signature.png" sig.png
check "--signature simulates no effect" grep -q "simulated  (none)" err.txt

finish

#!/bin/sh
# tests/stdlib.sh: every file of lucent's stdlib/ parses on its own (it
# includes what it needs) and all of them together, with no warning or
# error: for each stdlib/NAME.inc and stdlib/NAME.map (a colour map file,
# which declares its map: POV-Ray's scenes include it, then say
# color_map { M_Name }) a scene "#version 3.7; #include NAME" must render
# with exit status 0 and print nothing on stderr; then one scene including
# every file. Then the deprecated textures of glass_old.inc warn on use,
# once each, as POV-Ray's do. Last, meshmaker.inc's mesh files: lucent
# runs tests/stdlib-meshmaker/write.pov twice in an empty folder, and the
# files and #debug streams must be byte for byte what POV-Ray 3.7 wrote
# (tests/stdlib-meshmaker/expected, made by its record.sh).
. "${top_srcdir:-.}/tests/lib.sh"
lib="$top_srcdir/stdlib"
cd "$WORK" || exit 1
all=""
for path in "$lib"/*.inc "$lib"/*.map; do
	name=$(basename "$path")
	all="$all#include \"$name\"
"
	printf '#version 3.7;\n#include "%s"\n' "$name" > scene.pov
	"$LUCENT" -q +W8 +H6 scene.pov +O"$WORK/out.png" < /dev/null > err.txt 2>&1
	rc=$?
	if [ $rc -eq 0 ] && [ ! -s err.txt ]; then
		pass "$name alone"
	else
		fail "$name alone: exit status $rc"
		sed 's/^/    | /' err.txt | head -n 5
	fi
done
printf '#version 3.7;\n%s' "$all" > scene.pov
"$LUCENT" -q +W8 +H6 scene.pov +O"$WORK/out.png" < /dev/null > err.txt 2>&1
rc=$?
if [ $rc -eq 0 ] && [ ! -s err.txt ]; then
	pass "all files together"
else
	fail "all files together: exit status $rc"
	sed 's/^/    | /' err.txt | head -n 5
fi

# POV-Ray 3.7 warns at lines 3, 5 and 6 of this scene, with these texts
# (and not about the finish, the interior or the second use of T_Glass1).
cat > scene.pov <<'EOF'
#version 3.7;
#include "glass_old.inc"
#declare A = T_Glass1;
#declare B = texture { T_Glass1 };
#declare C = texture { T_Vicksbottle_Glass };
object { sphere { 0, 1 } material { texture { T_Glass4 } interior { I_Glass } } }
#declare D = finish { F_Glass2 };
EOF
"$LUCENT" -q +W8 +H6 scene.pov +O"$WORK/out.png" < /dev/null > err.txt 2>&1
rc=$?
grep 'warning' err.txt > got.txt
cat > want.txt <<'EOF'
scene.pov:3:14: warning: See notes in glass_old.inc regarding use of this deprecated texture: T_Glass1
scene.pov:5:24: warning: See notes in glass_old.inc regarding use of this deprecated texture: T_Vicksbottle_Glass
scene.pov:6:47: warning: See notes in glass_old.inc regarding use of this deprecated texture: T_Glass4
EOF
if [ $rc -eq 0 ] && cmp -s got.txt want.txt; then
	pass "glass_old.inc textures warn once each"
else
	fail "glass_old.inc warnings: exit status $rc"
	diff want.txt got.txt | sed 's/^/    | /' | head -n 10
fi

mm="$top_srcdir/tests/stdlib-meshmaker"
mkdir "$WORK/mm" && cp "$mm/write.pov" "$WORK/mm/" || exit 1
ok=1
for run in 1 2; do
	(cd "$WORK/mm" && "$LUCENT" -q -F +W8 +H8 +GDrun$run.dbg write.pov < /dev/null > err.txt 2>&1) || ok=0
done
for path in "$mm"/expected/*; do
	f=$(basename "$path")
	if ! cmp -s "$path" "$WORK/mm/$f"; then
		ok=0
		echo "    | $f differs from POV-Ray's"
		diff "$path" "$WORK/mm/$f" 2>&1 | sed 's/^/    | /' | head -n 6
	fi
done
if [ $ok -eq 1 ]; then
	pass "meshmaker.inc writes and reads its files as POV-Ray's"
else
	fail "meshmaker.inc files"
	sed 's/^/    | /' "$WORK/mm/err.txt" | head -n 5
fi
finish

#!/bin/sh
# tests/keywords.sh: every reserved word of grammar/keywords.txt
#   (a) is listed in the "Reserved words" section of doc/language.md, and
#       that section lists no word that is not reserved;
#   (b) is known to the lexer as a reserved word.
#
# (b) is checked in two ways:
#   - for all words at once, in one run of lucent: each word W is given a
#     value with Declare=W=1 (an .ini file), which binds the name without
#     going through the lexer, and the scene asks `#ifdef (W)`. A word the
#     lexer knows is a keyword there, never an identifier, so it reads as
#     undefined; a word missing from the lexer's table would be the
#     declared identifier and print itself. A non-keyword probe declared
#     the same way must print, which shows the method can fail.
#   - with the message itself: `#declare W = 1;` must fail with
#     "'W' is a reserved word and cannot be declared". Each such scene is a
#     run of lucent, and a run costs about 0.2 s (mostly loading the
#     shared libraries), so 500 of them take well over a minute; by default
#     this is done for a sample (every 25th word, and the last), and for
#     every word when KEYWORDS_FULL=1 is set.
#   A non-keyword identifier must be accepted by #declare.
#
# Environment (set by `make check`): top_srcdir, LUCENT.
: "${top_srcdir:=$(cd "$(dirname "$0")/.." && pwd)}"
: "${LUCENT:=$top_srcdir/lucent}"
case $LUCENT in
/*) ;;
*) LUCENT="$(pwd)/$LUCENT" ;;
esac
. "$top_srcdir/tests/lib.sh"

# Passing checks are only counted; failures are printed.
pass() { npass=$((npass + 1)); }

kwfile="$top_srcdir/grammar/keywords.txt"
doc="$top_srcdir/doc/language.md"
probe=lucent_kwtest_probe

if [ ! -f "$kwfile" ]; then
	fail "no $kwfile"
	finish
	exit 1
fi
grep -v '^#' "$kwfile" | grep -v '^[[:space:]]*$' > "$WORK/words"
nwords=$(wc -l < "$WORK/words" | tr -d ' ')
echo "$nwords reserved words in grammar/keywords.txt"

# ---- (a) the documentation ----

if [ ! -f "$doc" ]; then
	fail "no $doc"
else
	# The section: from its heading to the next level-2 heading.
	awk '/^## Reserved words[[:space:]]*$/ { on = 1; print; next }
	     on && /^## / { exit }
	     on { print }' "$doc" > "$WORK/section"
	if [ ! -s "$WORK/section" ]; then
		fail "doc/language.md has no '## Reserved words' section"
	fi
	# Every `word` written in the section's lists (lines "- **a**: ...").
	grep '^- \*\*' "$WORK/section" | tr ',' '\n' |
		sed -n 's/.*`\([^`]*\)`.*/\1/p' | sort -u > "$WORK/listed"
	while IFS= read -r w; do
		if grep -qxF -- "$w" "$WORK/listed"; then
			pass "doc lists $w"
		else
			fail "doc/language.md: '$w' is not listed in the Reserved words section"
		fi
	done < "$WORK/words"
	sort -u "$WORK/words" > "$WORK/words.sorted"
	comm -13 "$WORK/words.sorted" "$WORK/listed" > "$WORK/extra"
	if [ -s "$WORK/extra" ]; then
		while IFS= read -r w; do
			fail "doc/language.md lists '$w', which is not in grammar/keywords.txt"
		done < "$WORK/extra"
	else
		pass "doc lists no other word"
	fi
fi

# ---- (b) the lexer ----

if [ ! -x "$LUCENT" ]; then
	fail "lucent binary not found: $LUCENT"
	finish
	exit 1
fi
cd "$WORK" || exit 1

# All words at once.
{
	while IFS= read -r w; do
		echo "Declare=$w=1"
	done < words
	echo "Declare=$probe=1"
} > words.ini
{
	while IFS= read -r w; do
		printf '#ifdef (%s) #debug "%s\\n" #end\n' "$w" "$w"
	done < words
	printf '#ifdef (%s) #debug "%s\\n" #end\n' "$probe" "$probe"
} > batch.pov
"$LUCENT" -q -F +W8 +H8 +GDbatch.out words.ini batch.pov > batch.err 2>&1
rc=$?
[ -f batch.out ] || : > batch.out
if [ $rc -ne 0 ]; then
	fail "the batch scene failed (exit status $rc):"
	sed 's/^/    | /' batch.err | head -n 10
else
	if grep -qxF "$probe" batch.out; then
		pass "the probe identifier is declared"
	else
		fail "the non-keyword probe '$probe' did not read as declared: the batch check cannot work"
	fi
	while IFS= read -r w; do
		if grep -qxF -- "$w" batch.out; then
			fail "'$w' is not a keyword to the lexer: it read as the identifier declared by Declare=$w=1"
		else
			pass "$w is a keyword"
		fi
	done < words
fi

# The message, for a sample of the words (or all of them).
expect_reserved() {
	w=$1
	# `#declare deprecated X` marks X deprecated, so the word itself is
	# tried where the identifier goes after that prefix.
	if [ "$w" = deprecated ]; then
		printf '#declare deprecated %s = 1;\n' "$w" > one.pov
		col=21
	else
		printf '#declare %s = 1;\n' "$w" > one.pov
		col=10
	fi
	"$LUCENT" -q -F +W8 +H8 one.pov > one.err 2>&1
	rc=$?
	msg="one.pov:1:$col: error: '$w' is a reserved word and cannot be declared"
	if [ $rc -eq 1 ] && grep -qxF -- "$msg" one.err; then
		pass "#declare $w"
	else
		fail "#declare $w = 1; (exit status $rc) did not give: $msg"
		sed 's/^/    | /' one.err | head -n 5
	fi
}
if [ "${KEYWORDS_FULL:-0}" = 1 ]; then
	cp words sample
else
	awk -v last="$nwords" '(NR - 1) % 25 == 0 || NR == last' words > sample
fi
while IFS= read -r w; do
	expect_reserved "$w"
done < sample
echo "checked the #declare message for $(wc -l < sample | tr -d ' ') of the words"

# A word that is not reserved is an ordinary identifier.
printf '#declare %s = 1;\n#debug concat(str(%s, 0, 0), "\\n")\n' "$probe" "$probe" > ident.pov
"$LUCENT" -q -F +W8 +H8 +GDident.out ident.pov > ident.err 2>&1
rc=$?
if [ $rc -eq 0 ] && [ "$(cat ident.out 2>/dev/null)" = 1 ]; then
	pass "#declare $probe"
else
	fail "#declare $probe = 1; was not accepted (exit status $rc)"
	sed 's/^/    | /' ident.err | head -n 5
fi

finish

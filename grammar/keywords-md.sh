#!/bin/sh
# keywords-md.sh: print the "Reserved words" section of doc/language.md
# from grammar/keywords.txt.
#
#   grammar/keywords-md.sh [KEYWORDS.TXT [SRC_LANG_DIR]]
#
# The defaults are keywords.txt beside this script and ../src/lang. The
# words are split in two lists: those the front end refers to somewhere
# (its parser files name KW_<WORD>), and those only reserved so far. Paste
# the output over the section (everything from "## Reserved words" to the
# end of doc/language.md); tests/keywords.sh checks that every word is
# there.
# The word lists are split on white space on purpose.
# shellcheck disable=SC2086
set -e
here=$(cd "$(dirname "$0")" && pwd)
kw=${1:-$here/keywords.txt}
src=${2:-$here/../src/lang}
[ -f "$kw" ] || { echo "keywords-md.sh: no $kw" >&2; exit 1; }

words=$(grep -v '^#' "$kw" | grep -v '^[[:space:]]*$')
total=$(printf '%s\n' "$words" | wc -l | tr -d ' ')

# The parser's own files (not the generated keyword table).
files=""
for f in "$src"/*.c; do
	case $(basename "$f") in
	kw.c) ;;
	*) [ -f "$f" ] && files="$files $f" ;;
	esac
done

used=""
unused=""
for w in $words; do
	upper=$(printf '%s' "$w" | tr 'a-z' 'A-Z')
	if [ -n "$files" ] && grep -q -w "KW_$upper" $files; then
		used="$used $w"
	else
		unused="$unused $w"
	fi
done
nused=$(printf '%s\n' $used | grep -c . || true)
nunused=$(printf '%s\n' $unused | grep -c . || true)

# One bullet per initial letter: - **a**: `abs`, `acos`, ...
bullets() {
	printf '%s\n' "$@" | awk '
		NF == 0 { next }
		{
			c = substr($1, 1, 1)
			if (c != cur) {
				if (cur != "") printf "\n"
				printf "- **%s**: `%s`", c, $1
				cur = c
			} else {
				printf ", `%s`", $1
			}
		}
		END { if (cur != "") printf "\n" }'
}

cat <<EOF
## Reserved words

These $total words are reserved: the lexer reads each of them as a
keyword, never as an identifier, so none of them can be declared or used
as the name of a macro, a macro parameter or a \`#for\` variable
(\`#declare sphere = 1;\` is the error "'sphere' is a reserved word and
cannot be declared"); only \`x\`, \`y\`, \`z\`, \`u\` and \`v\` may name
the parameters of a user function. All are lower case, so an identifier
with an upper case letter in it never collides with one. The list is
\`grammar/keywords.txt\`, from which the lexer's keyword table is
generated; this section is generated from it by
\`grammar/keywords-md.sh\`, and \`tests/keywords.sh\` checks both.

### Words lucent gives a meaning ($nused)

These are the words the parser refers to somewhere: directives, built-in
identifiers and functions, colour and spline keywords, and the statements
and modifiers described above.

EOF
bullets $used
cat <<EOF

### Words reserved for POV-Ray features not implemented yet ($nunused)

These are reserved because POV-Ray 3.7 reserves them, but lucent does not
use them yet: writing one where lucent expects something else is a syntax
error ("expected ..., found 'cylinder'").

EOF
bullets $unused

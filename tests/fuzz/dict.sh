#!/bin/sh
# tests/fuzz/dict.sh: the libFuzzer dictionary, made from grammar/ (the
# single source of the reserved words and directives).
#   dict.sh TOP_SRCDIR > lucent.dict
set -e
top=${1:-.}
# Every reserved word.
grep -v '^#' "$top/grammar/keywords.txt" | grep -v '^$' | sed 's/.*/"&"/'
# Directives: the reserved words named in the `directive` production of
# sdl.ebnf and in the message directives, with '#'.
words=$(grep -v '^#' "$top/grammar/keywords.txt" | grep -v '^$')
{ sed -n '/^directive *=/,/;/p' "$top/grammar/sdl.ebnf"
  grep -o '"#" *, *"[a-z_]*"' "$top/grammar/sdl.ebnf"
  sed -n '/^switch *=/,/;/p; /^message *=/p' "$top/grammar/sdl.ebnf"; } |
	tr -c 'a-z_\n' ' ' | tr ' ' '\n' | grep -v '^$' | sort -u |
	grep -Fx "$words" | sed 's/.*/"#&"/'
# Punctuation and operators of the lexer.
for t in '{' '}' '(' ')' '[' ']' '<' '>' '<=' '>=' '!=' '=' ',' ';' '.' '?' ':' '&' '|' '!' '+' '-' '*' '/' '/*' '*/' '//' '\"' '\\n'; do
	printf '"%s"\n' "$t"
done

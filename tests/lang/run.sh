#!/bin/sh
# tests/lang/run.sh: the language test corpus.
#
# Every tests/lang/<name>.pov is a small program that prints its results
# with #debug; tests/lang/<name>.expected holds what POV-Ray 3.7 prints for
# it (made by record.sh). This script copies tests/lang to a temporary
# folder and, from inside that folder, runs for each program
#   $LUCENT -q -F +W8 +H8 +GD<tmp>/<name>.out <name>.pov
# A program passes when lucent exits with status 0 and <name>.out is byte
# for byte the same as <name>.expected.
#
#   tests/lang/run.sh                    every program
#   tests/lang/run.sh expr-add-sub.pov … only these (names or paths)
#
# Environment: LUCENT (the lucent binary), LUCENT_STDLIB, top_srcdir, as
# set by `make check`; LANG_TIMEOUT (seconds per program, default 60).
: "${top_srcdir:=$(cd "$(dirname "$0")/../.." && pwd)}"
: "${LUCENT:=$top_srcdir/lucent}"
export LUCENT_STDLIB="${LUCENT_STDLIB:-$top_srcdir/stdlib}"
src="$top_srcdir/tests/lang"
[ -d "$src" ] || src=$(cd "$(dirname "$0")" && pwd)
case $LUCENT in
/*) ;;
*) LUCENT="$(pwd)/$LUCENT" ;;
esac
if [ ! -x "$LUCENT" ]; then
	echo "run.sh: lucent binary not found: $LUCENT" >&2
	exit 1
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/lucent-lang.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
trap 'exit 2' INT TERM
cp -R "$src/." "$tmp/" || exit 1
cd "$tmp" || exit 1

# A hung program must not hang `make check`.
timeout_cmd=""
if command -v timeout > /dev/null 2>&1; then
	timeout_cmd="timeout ${LANG_TIMEOUT:-60}"
fi

if [ $# -eq 0 ]; then
	set -- *.pov
fi

# Programs that need a capability of a later issue are listed in
# pending.list ("name  reason"); they are run, reported as SKIP while they
# fail, and fail the run once they pass, so the list stays honest.
pending() { grep -q "^$1[[:space:]]" "$src/pending.list" 2>/dev/null; }

npass=0
nfail=0
nskip=0
for prog in "$@"; do
	name=$(basename "$prog" .pov)
	if [ ! -f "$name.pov" ]; then
		nfail=$((nfail + 1))
		echo "FAIL: $name (no such program)"
		continue
	fi
	if [ ! -f "$name.expected" ]; then
		nfail=$((nfail + 1))
		echo "FAIL: $name (no $name.expected; run tests/lang/record.sh)"
		continue
	fi
	rm -f "$name.out"
	$timeout_cmd "$LUCENT" -q -F +W8 +H8 +GD"$tmp/$name.out" "$name.pov" \
		> "$tmp/$name.stdout" 2> "$tmp/$name.stderr"
	rc=$?
	[ -f "$name.out" ] || : > "$name.out"
	if pending "$name"; then
		if [ $rc -eq 0 ] && cmp -s "$name.expected" "$name.out"; then
			nfail=$((nfail + 1))
			echo "FAIL: $name passes now: remove it from tests/lang/pending.list"
		else
			nskip=$((nskip + 1))
			echo "SKIP: $name ($(grep "^$name[[:space:]]" "$src/pending.list" | sed 's/^[^[:space:]]*[[:space:]]*//'))"
		fi
		continue
	fi
	if [ $rc -eq 0 ] && cmp -s "$name.expected" "$name.out"; then
		npass=$((npass + 1))
		echo "PASS: $name"
	else
		nfail=$((nfail + 1))
		if [ $rc -ne 0 ]; then
			why="exit status $rc"
			[ $rc -eq 124 ] && [ -n "$timeout_cmd" ] && why="timed out"
		else
			why="output differs"
		fi
		echo "FAIL: $name ($why)"
		if ! cmp -s "$name.expected" "$name.out"; then
			diff -u "$name.expected" "$name.out" | sed -n '3,14p' | sed 's/^/    | /'
		fi
		if [ -s "$tmp/$name.stderr" ]; then
			echo "    stderr:"
			head -n 8 "$tmp/$name.stderr" | sed 's/^/    ! /'
		fi
	fi
done
echo "$npass passed, $nfail failed, $nskip skipped"
[ "$nfail" -eq 0 ]

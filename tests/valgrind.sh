#!/bin/sh
# tests/valgrind.sh: the unit tests and the language tests under valgrind's
# memcheck (`make check-valgrind`). A program passes when it passes as in
# `make check` and memcheck reports no error (invalid read or write, use of
# an uninitialised value, bad free) and no leak: definitely, indirectly and
# possibly lost blocks all count (--errors-for-leak-kinds); memory still
# reachable at exit does not (libraries' own caches).
#
#   tests/valgrind.sh UNIT_TEST...      the given unit test programs, then
#                                       every tests/lang program
#
# Each program's valgrind report is kept in $VG_LOGDIR (default
# valgrind-logs/ in the current folder) as NAME.vg (lang: lang-NAME.vg,
# one per process), and a failing one is printed. Ends with
# "N passed, M failed"; exit status 1 on a failure, 77 (skip) without
# valgrind.
#
# Environment: LUCENT (the lucent binary), LUCENT_STDLIB, top_srcdir, as
# set by make; VALGRIND (default valgrind); VG_LOGDIR; valgrind's own
# VALGRIND_OPTS (e.g. --track-origins=yes to find where an uninitialised
# value came from: left out by default, it doubles the time).
: "${top_srcdir:=$(cd "$(dirname "$0")/.." && pwd)}"
: "${LUCENT:=$PWD/lucent}"
VALGRIND=${VALGRIND:-valgrind}
VG_LOGDIR=${VG_LOGDIR:-$PWD/valgrind-logs}
if ! command -v "$VALGRIND" > /dev/null 2>&1; then
	echo "SKIP: $VALGRIND not found"
	exit 77
fi
case $LUCENT in
/*) ;;
*) LUCENT=$PWD/$LUCENT ;;
esac
case $VG_LOGDIR in
/*) ;;
*) VG_LOGDIR=$PWD/$VG_LOGDIR ;;
esac
rm -rf "$VG_LOGDIR"
mkdir -p "$VG_LOGDIR" || exit 1

# shellcheck source=tests/lib.sh
. "$top_srcdir/tests/lib.sh"

# Exit status 99 marks a memcheck error, so that it is told from a test's
# own failure.
VG_OPTS="-q --error-exitcode=99 --suppressions=$top_srcdir/tests/valgrind.supp --leak-check=full --show-leak-kinds=definite,indirect,possible \
--errors-for-leak-kinds=definite,indirect,possible --num-callers=30"

# show LOG: print a failing program's valgrind report (at most 60 lines).
show() {
	[ -s "$1" ] && sed -n '1,60p' "$1" | sed 's/^/    /'
}

# 1. Unit tests (cmocka programs), one valgrind run each.
for t in "$@"; do
	name=$(basename "$t")
	log=$VG_LOGDIR/$name.vg
	# shellcheck disable=SC2086 # $VG_OPTS is a list of options
	"$VALGRIND" $VG_OPTS --log-file="$log" "$t" > "$VG_LOGDIR/$name.out" 2>&1
	rc=$?
	case $rc in
	0) pass "$name" ;;
	99)
		fail "$name: memcheck errors or leaks ($log)"
		show "$log"
		;;
	*)
		fail "$name: the test failed under valgrind (status $rc; $VG_LOGDIR/$name.out)"
		show "$log"
		;;
	esac
done

# 2. The language tests, with lucent run through valgrind by a wrapper
# (tests/lang/run.sh needs LUCENT to be one executable file).
wrap=$WORK/lucent-vg
cat > "$wrap" << EOF
#!/bin/sh
exec "$VALGRIND" $VG_OPTS --log-file="$VG_LOGDIR/lang-%p.vg" "$LUCENT" "\$@"
EOF
chmod +x "$wrap"
# Under valgrind a program runs 20 to 50 times slower.
LUCENT=$wrap LANG_TIMEOUT=${LANG_TIMEOUT:-600} sh "$top_srcdir/tests/lang/run.sh" \
	> "$WORK/lang.out" 2>&1
lang_rc=$?
grep -v '^PASS:' "$WORK/lang.out"
# run.sh counts a program failed by memcheck (status 99) as failed; name
# the reports that hold errors.
nbad=0
for log in "$VG_LOGDIR"/lang-*.vg; do
	[ -s "$log" ] || continue
	if grep -q 'ERROR SUMMARY: [1-9]\|definitely lost\|indirectly lost\|possibly lost\|Invalid \|uninitialised' "$log"; then
		nbad=$((nbad + 1))
		echo "memcheck report: $log"
		show "$log"
	fi
done
if [ $lang_rc -eq 0 ] && [ $nbad -eq 0 ]; then
	pass "tests/lang under memcheck: $(tail -n 1 "$WORK/lang.out")"
else
	fail "tests/lang under memcheck: $(tail -n 1 "$WORK/lang.out"); $nbad report(s) with errors"
fi
finish

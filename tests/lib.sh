# tests/lib.sh: shared helpers for the shell tests (sourced, not run).
# Each test script counts its checks and ends with "N passed, M failed".
: "${LUCENT:=$PWD/lucent}"
: "${top_srcdir:=$PWD}"
export LUCENT_STDLIB="${LUCENT_STDLIB:-$top_srcdir/stdlib}"
npass=0
nfail=0
WORK=$(mktemp -d "${TMPDIR:-/tmp}/lucent-test.XXXXXX")
trap 'rm -rf "$WORK"' EXIT

pass() { npass=$((npass + 1)); echo "PASS: $1"; }
fail() { nfail=$((nfail + 1)); echo "FAIL: $1"; }

# check NAME COMMAND...: pass if the command succeeds.
check() {
	name=$1
	shift
	if "$@"; then pass "$name"; else fail "$name"; fi
}

# contains FILE TEXT: the file contains the literal text.
contains() { grep -qF -- "$2" "$1"; }

finish() {
	echo "$npass passed, $nfail failed"
	[ "$nfail" -eq 0 ]
}

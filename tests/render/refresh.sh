#!/bin/sh
# tests/render/refresh.sh: regenerate the reference images of the render
# tests, for every scene in tests/render/*.list (or only the scenes
# named on the command line):
#   tests/render/povray/NAME.png    POV-Ray 3.7's render of scenes/NAME.pov
#   tests/render/expected/NAME.png  lucent's render, which run.sh must then
#                                   reproduce exactly
# It works from any folder (make refresh-references runs it). Run it after
# any deliberate change to rendering, then look at the new images and at
# run.sh's figures against POV-Ray before committing them.
#
# Environment: LUCENT (default ./lucent), POVRAY (default povray),
# LUCENT_STDLIB (default the source tree's stdlib/).
top=$(cd "$(dirname "$0")/../.." && pwd) || exit 1
LUCENT=${LUCENT:-./lucent}
# A path relative to where we were started, made absolute before the cd.
case $LUCENT in
/*) ;;
*/*) LUCENT=$PWD/$LUCENT ;;
esac
POVRAY=${POVRAY:-povray}
LUCENT_STDLIB=${LUCENT_STDLIB:-$top/stdlib}
export LUCENT_STDLIB
cd "$top" || exit 1

log=$(mktemp "${TMPDIR:-/tmp}/lucent-refresh.XXXXXX") || exit 1
list=$log.list
trap 'rm -f "$log" "$list"' EXIT
cat tests/render/*.list > "$list" || exit 1
mkdir -p tests/render/povray tests/render/expected

# wanted NAME: is the scene selected by the command line (all if none)?
wanted() {
	[ $# -eq 1 ] && return 0
	n=$1
	shift
	for a in "$@"; do
		[ "$a" = "$n" ] && return 0
	done
	return 1
}

status=0
count=0
while read -r name w h opts; do
	case $name in '' | '#'*) continue ;; esac
	sw=""
	case $opts in *'|'*) sw=${opts#*|} ;; esac
	wanted "$name" "$@" || continue
	count=$((count + 1))
	scene=scenes/$name.pov
	if [ ! -f "$scene" ]; then
		echo "$name: no $scene" >&2
		status=1
		continue
	fi
	# shellcheck disable=SC2086 # the switches are meant to be split
	if ! "$POVRAY" -D -V +W"$w" +H"$h" $sw +I"$scene" +Otests/render/povray/"$name".png \
			< /dev/null > "$log" 2>&1; then
		echo "$name: povray failed:" >&2
		sed 's/^/  /' "$log" >&2
		status=1
	fi
	# shellcheck disable=SC2086
	if ! "$LUCENT" -q +W"$w" +H"$h" $sw "$scene" +Otests/render/expected/"$name".png \
			< /dev/null > "$log" 2>&1; then
		echo "$name: lucent failed:" >&2
		sed 's/^/  /' "$log" >&2
		status=1
	elif [ -s "$log" ]; then
		sed "s/^/$name: /" "$log"
	fi
	echo "$name: ${w}x$h done"
done < "$list"
if [ "$count" -eq 0 ]; then
	echo "no scene selected from $list" >&2
	exit 1
fi
exit $status

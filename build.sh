#!/bin/sh
# build.sh: the README's first quick-start command. On Debian 12 it installs
# what lucent needs (as root, or through sudo), then bootstraps, configures,
# builds, and renders scenes/showcase.pov to showcase.png.
#   ./build.sh                 everything
#   CONFIGURE_FLAGS=... ./build.sh   extra ./configure flags (CI: --enable-werror;
#                                    fuzzing: "--enable-fuzz CC=clang CXX=clang++")
#   EXTRA_PACKAGES="clang valgrind" ./build.sh   also install these (CI)
set -e
cd "$(dirname "$0")"

# Build tools and libraries; POV-Ray and its includes are the references the
# tests and the cross-check scripts compare against; gnuplot draws the
# plots of make accuracy; the Liberation and DejaVu fonts stand in for
# POV-Ray's own fonts in text objects when fonts-povray is not installed.
PACKAGES="build-essential autoconf automake pkg-config gperf libopenimageio-dev \
openimageio-tools libpng-dev zlib1g-dev libcmocka-dev povray povray-includes python3-numpy gnuplot-nox \
fonts-liberation fonts-dejavu-core"
# The fuzz harnesses (CONFIGURE_FLAGS="--enable-fuzz CC=clang CXX=clang++",
# then make fuzz) need clang and its libFuzzer.
case " $CONFIGURE_FLAGS " in
*" --enable-fuzz "*) PACKAGES="$PACKAGES clang" ;;
esac
# EXTRA_PACKAGES: more to install, for the targets that need them: CI's
# make check-fuzz (clang) and make check-valgrind (valgrind).
PACKAGES="$PACKAGES $EXTRA_PACKAGES"

missing=""
for p in $PACKAGES; do
	dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
	if [ "$(id -u)" = 0 ]; then SUDO=""; else SUDO="sudo"; fi
	echo "build.sh: installing:$missing"
	$SUDO apt-get update
	DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends $missing
fi

./bootstrap
# shellcheck disable=SC2086
./configure $CONFIGURE_FLAGS
make -j"$(nproc)"
./lucent scenes/showcase.pov +W800 +H600 +Oshowcase.png
echo "build.sh: rendered showcase.png"

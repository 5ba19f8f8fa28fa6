#!/usr/bin/env bash
# Builds fmusim, the FMI Reference FMUs' command-line importer, from the
# sources here: tools/fmusim/build.sh OUT (the executable). Needs gcc and
# libxml2, minizip and zlib (Debian: libxml2-dev libminizip-dev zlib1g-dev;
# installed with apt-get when missing and allowed).
set -euo pipefail
out=$(realpath -m "$1")
here=$(cd "$(dirname "$0")" && pwd)
if ! { pkg-config --exists libxml-2.0 minizip zlib 2>/dev/null; }; then
    apt-get update -q > /dev/null
    apt-get install -y -q --no-install-recommends libxml2-dev libminizip-dev zlib1g-dev pkg-config > /dev/null
fi
cd "$here/fmusim"
gcc -O1 -w -I. -I../include $(pkg-config --cflags libxml-2.0 minizip zlib) \
    '-DFMUSIM_VERSION="Reference-FMUs c8d4e6d (trackgen: no CVODE)"' \
    *.c ../no_cvode.c ../src/*.c \
    -o "$out" $(pkg-config --libs libxml-2.0 minizip zlib) -ldl -lm

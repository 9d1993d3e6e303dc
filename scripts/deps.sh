#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# Install the Debian packages rdc needs, or say how.  Run by `make demo`
# and `make check`.  As root it installs what is missing with apt-get; as
# anyone else it prints the one apt-get line to run and fails.
set -e

PKGS="gcc make pkg-config libc6-dev libpng-dev zlib1g-dev libcmocka-dev libvncserver-dev clang libclang-rt-14-dev"
# `--peers`: also the libraries `make bench-peers` measures rdc against.
PEER_PKGS="libpixman-1-dev libcairo2-dev libsdl2-gfx-dev"
[ "$1" = "--peers" ] && PKGS="$PKGS $PEER_PKGS"

missing=""
for p in $PKGS; do
	if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
		missing="$missing $p"
	fi
done
[ -z "$missing" ] && exit 0

if [ "$(id -u)" = 0 ]; then
	echo "deps: installing$missing"
	export DEBIAN_FRONTEND=noninteractive
	apt-get install -y --no-install-recommends $missing >/dev/null ||
		{ apt-get update >/dev/null && apt-get install -y --no-install-recommends $missing >/dev/null; }
	exit 0
fi
echo "deps: missing Debian packages; run as root:" >&2
echo "  apt-get install -y$missing" >&2
exit 1

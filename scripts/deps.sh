#!/bin/sh
# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# Install the Debian packages rdc needs, or say how.  Run by `make demo`
# and `make check`.  As root it installs what is missing with apt-get; as
# anyone else it prints the one apt-get line to run and fails.
set -e

PKGS="gcc make pkg-config libc6-dev libpng-dev zlib1g-dev libcmocka-dev libvncserver-dev clang libclang-rt-14-dev libusb-1.0-0-dev sigrok-cli libdrm-dev clang-format reuse"
# libusb-1.0's static link flags name -ludev: make install-check links
# examples/hello.c with `pkg-config --static --libs rdc`
PKGS="$PKGS libudev-dev"
# the firmware image and its test (make firmware-mcu, make mcu-test)
PKGS="$PKGS gcc-arm-none-eabi qemu-system-arm"
# test_dist: the manual pages through groff and man --warnings, the bash
# completion with bash-completion's helpers, the units through
# systemd-analyze verify
PKGS="$PKGS groff-base man-db bash-completion systemd"
# test_web_browser: the web sink's page in headless Chromium, driven
# through chromedriver by tests/web/browser.py
PKGS="$PKGS python3 chromium chromium-driver"
# the Python bindings' tests (tests/python/run.sh): pytest for them and
# the plugin, numpy for frames as arrays, pycodestyle for their layout
PKGS="$PKGS python3-pytest python3-numpy pycodestyle"
# libgpiod's v2 API (GPIO lines): Debian 13 has it in main; Debian 12 only
# in bookworm-backports, which is enabled for these two packages alone
# (apt-get -t for them, the rest stays on bookworm).
GPIOD_PKGS="libgpiod-dev gpiod"
# `--peers`: also the libraries `make bench-peers` measures rdc against.
PEER_PKGS="libpixman-1-dev libcairo2-dev libsdl2-gfx-dev"
[ "$1" = "--peers" ] && PKGS="$PKGS $PEER_PKGS"
# `--debs`: what `make debs` needs to build the Debian packages (debian/)
# and check them.
DEB_PKGS="dpkg-dev debhelper dh-dkms dh-python lintian"
[ "$1" = "--debs" ] && PKGS="$PKGS $DEB_PKGS"

missing=""
for p in $PKGS; do
	if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
		missing="$missing $p"
	fi
done
gpiod_ok() {
	pkg-config --atleast-version=2.0 libgpiod 2>/dev/null &&
		command -v gpiomon >/dev/null 2>&1 &&
		gpiomon --version 2>/dev/null | grep -q 'v2\.'
}
gpiod_missing=""
gpiod_ok || gpiod_missing=1
[ -z "$missing" ] && [ -z "$gpiod_missing" ] && exit 0

if [ "$(id -u)" = 0 ]; then
	export DEBIAN_FRONTEND=noninteractive
	# Wait for another apt or dpkg (an unattended upgrade, a second
	# install) rather than fail at once on its lock.
	APT_WAIT="-o DPkg::Lock::Timeout=600"
	if [ -n "$missing" ]; then
		echo "deps: installing$missing"
		apt-get $APT_WAIT install -y --no-install-recommends $missing >/dev/null ||
			{ apt-get $APT_WAIT update >/dev/null && apt-get $APT_WAIT install -y --no-install-recommends $missing >/dev/null; }
	fi
	if [ -n "$gpiod_missing" ]; then
		. /etc/os-release
		target=""
		if [ "${VERSION_CODENAME:-}" = bookworm ]; then
			target="-t bookworm-backports"
			src=/etc/apt/sources.list.d/rdc-backports.sources
			if ! grep -rqs bookworm-backports /etc/apt/sources.list /etc/apt/sources.list.d; then
				echo "deps: enabling bookworm-backports for $GPIOD_PKGS"
				printf '%s\n' "Types: deb" "URIs: http://deb.debian.org/debian" \
					"Suites: bookworm-backports" "Components: main" \
					"Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg" >"$src"
			fi
			apt-get $APT_WAIT update >/dev/null
		fi
		echo "deps: installing $GPIOD_PKGS${target:+ ($target)}"
		apt-get $APT_WAIT install -y --no-install-recommends $target $GPIOD_PKGS >/dev/null ||
			echo "deps: libgpiod v2 could not be installed: building without GPIO lines" >&2
	fi
	exit 0
fi
[ -n "$gpiod_missing" ] && missing="$missing (and, from bookworm-backports: apt-get install -t bookworm-backports $GPIOD_PKGS)"
echo "deps: missing Debian packages; run as root:" >&2
echo "  apt-get install -y$missing" >&2
exit 1

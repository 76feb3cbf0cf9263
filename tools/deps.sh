# shellcheck shell=bash
# Sourced by tools/run and tools/test: installs the Debian 12 packages edaha needs that are
# missing. Only missing ones, so a second run costs nothing and needs no network.

BUILD_PKGS="meson ninja-build pkg-config gcc libc6-dev libjson-c-dev libyaml-dev libpng-dev
 libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri libinput-dev libevdev-dev libgpiod-dev
 libdrm-dev libgbm-dev libudev-dev libseat-dev libfreetype-dev fonts-vlgothic libsystemd-dev
 libassimp-dev libsdl2-dev"
TEST_PKGS="clang libclang-rt-14-dev assimp-utils
 qemu-system-x86 linux-image-amd64 busybox-static cpio kmod udev seatd
 linux-source-6.1 linux-headers-amd64 make xz-utils bc systemd
 mtools dosfstools exfatprogs e2fsprogs python3 xvfb xauth xdotool"
# tests/export/blender.sh: Blender's glTF importer plays model.glb's wind (issue 26); with
# numpy for the importer: 150 packages, 168 MB to download, 633 MB installed on a machine
# that has the rest
TEST_PKGS+=" blender python3-numpy"
# tests/export/threejs.sh: three.js (Debian's libjs-three) plays the same wind in headless
# Chromium
TEST_PKGS+=" chromium libjs-three"
# tests/export/page.sh: the take-home page in a second browser engine, Firefox (Gecko)
TEST_PKGS+=" firefox-esr"

deps_install() {
	local missing=() p
	for p in "$@"; do
		dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
	done
	# Node.js for the Khronos glTF validator: any installed node will do.
	if [ "${DEPS_NODE:-0}" = 1 ] && ! command -v npm >/dev/null; then
		command -v node >/dev/null || missing+=(nodejs)
		missing+=(npm)
	fi
	[ ${#missing[@]} -eq 0 ] && return 0
	echo "edaha: installing ${missing[*]}"
	local sudo=()
	[ "$(id -u)" -eq 0 ] || sudo=(sudo)
	"${sudo[@]}" apt-get update -qq
	DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends \
		"${missing[@]}" >/dev/null
}
# tools/deb-test.sh: the Debian package (debian/), lintian, a throw-away bookworm root
TEST_PKGS+=" debhelper dpkg-dev fakeroot lintian mmdebstrap git"

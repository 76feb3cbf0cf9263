#!/bin/bash
# Builds the kiosk OS: Debian 12 (bookworm) from Debian packages, plus edaha's own package
# built from this checkout (debian/), booting straight into the kiosk. See images/README.md.
#
#   images/build.sh ARCH OUT
#     ARCH  amd64: root.img (ext4) + vmlinuz + initrd.img for QEMU (images/boot-test.sh)
#           arm64: disk.img, an SD card for a Raspberry Pi 4 (FAT boot + ext4 root)
#     OUT   the directory the image and its files go to (created; files in it replaced)
#   Environment:
#     MIRROR, SECURITY_MIRROR  Debian mirrors (default http://deb.debian.org/debian,
#                     http://deb.debian.org/debian-security)
#     SNAPSHOT        a snapshot.debian.org time (20250520T000000Z): both mirrors are that
#                     day's archive, so a later build installs the same versions
#     SOURCE_DATE_EPOCH  the time stamp of every file in the image (default: the time of the
#                     checkout's last commit)
#     IMAGE_CACHE     keeps downloaded packages between builds (default /tmp/edaha-image-cache)
#     IMAGE_SIZE_MB   the root filesystem's size (default: what it holds plus 512 MiB)
#     PACKAGE_ONLY=1  only build edaha_VERSION_ARCH.deb into OUT (step 1), no image
#
# Two mmdebstrap runs: a build chroot (the machine's architecture, with ARCH's -dev
# packages, a cross compiler when ARCH is another) where dpkg-buildpackage builds
# edaha_VERSION_ARCH.deb, then the image's root, which installs it with the other packages
# and where images/customize.sh makes it a kiosk. The .deb is kept in OUT. The disk image is made
# from files (mkfs.ext4 -d, mkfs.vfat + mtools, sfdisk): no loop device, nothing mounted.
# Runs as root (mmdebstrap's chroots). arm64 on another machine runs the packages'
# scripts through qemu-user (images/foreign.sh).
# Packages: mmdebstrap e2fsprogs git dpkg-dev; arm64: dosfstools mtools fdisk qemu-user-static
# arch-test (PACKAGE_ONLY=1: mmdebstrap git dpkg-dev).
set -euo pipefail
START=$(date +%s)
HERE=$(cd "$(dirname "$0")" && pwd)
REPO=$(cd "$HERE/.." && pwd)

die() { echo "build: $*" >&2; exit 1; }
step() { echo "build: [$(($(date +%s) - START)) s] $*"; }

[ $# -eq 2 ] || { echo "usage: images/build.sh amd64|arm64 OUT" >&2; exit 2; }
ARCH=$1
case $ARCH in amd64 | arm64) ;; *) die "ARCH is amd64 or arm64, not '$ARCH'" ;; esac
mkdir -p "$2"
OUT=$(realpath "$2")

need() { # program package
	command -v "$1" >/dev/null || die "no $1 (apt-get install $2)"
}
[ "$(id -u)" = 0 ] || die "run as root (sudo): mmdebstrap makes chroots"
need mmdebstrap mmdebstrap
need git git
need dpkg-parsechangelog dpkg-dev
[ "${PACKAGE_ONLY:-0}" = 1 ] || need mkfs.ext4 e2fsprogs
if [ "$ARCH" = arm64 ] && [ "${PACKAGE_ONLY:-0}" != 1 ]; then
	need mkfs.vfat dosfstools
	need mcopy mtools
	need sfdisk fdisk
fi

HOST_ARCH=$(dpkg --print-architecture)
SUITE=bookworm
if [ -n "${SNAPSHOT:-}" ]; then
	[[ $SNAPSHOT =~ ^[0-9]{8}T[0-9]{6}Z$ ]] || die "SNAPSHOT is a time like 20250520T000000Z, not '$SNAPSHOT'"
	MIRROR=http://snapshot.debian.org/archive/debian/$SNAPSHOT
	SECURITY_MIRROR=http://snapshot.debian.org/archive/debian-security/$SNAPSHOT
fi
MIRROR=${MIRROR:-http://deb.debian.org/debian}
SECURITY_MIRROR=${SECURITY_MIRROR:-http://deb.debian.org/debian-security}
# raspi-firmware is in non-free-firmware
COMPONENTS=main
[ "$ARCH" = arm64 ] && COMPONENTS="main non-free-firmware"
SOURCES=("deb $MIRROR $SUITE $COMPONENTS" "deb $MIRROR $SUITE-updates $COMPONENTS"
	"deb $SECURITY_MIRROR $SUITE-security $COMPONENTS")
APTOPTS=(--aptopt='Acquire::Retries "3"')
# a snapshot's Release files expire; their signatures still count
[ -n "${SNAPSHOT:-}" ] && APTOPTS+=(--aptopt='Acquire::Check-Valid-Until "false"')

if [ -z "${SOURCE_DATE_EPOCH:-}" ]; then
	SOURCE_DATE_EPOCH=$(git -C "$REPO" log -1 --format=%ct) || die "set SOURCE_DATE_EPOCH (not a git checkout)"
fi
[[ $SOURCE_DATE_EPOCH =~ ^[0-9]+$ ]] || die "SOURCE_DATE_EPOCH is seconds since 1970, not '$SOURCE_DATE_EPOCH'"
export SOURCE_DATE_EPOCH
VERSION=$(git -C "$REPO" describe --always --dirty --tags 2>/dev/null || echo unknown)

CACHE=${IMAGE_CACHE:-/tmp/edaha-image-cache}
mkdir -p "$CACHE/apt-build-$HOST_ARCH" "$CACHE/apt-$ARCH"
CACHE=$(realpath "$CACHE")
WORK=$(mktemp -d "$CACHE/work-$ARCH.XXXXXX")
chmod 755 "$WORK" # apt downloads as _apt
trap 'rm -rf "$WORK"' EXIT
export WORK ARCH HERE

# mmdebstrap's options that keep the downloaded .debs in the cache (DIR) between runs
apt_cache() {
	printf '%s\n' --skip=essential/unlink \
		"--setup-hook=mkdir -p \"\$1/var/cache/apt/archives\"" \
		"--setup-hook=sync-in $1 /var/cache/apt/archives/" \
		"--customize-hook=sync-out /var/cache/apt/archives $1"
}
# the package names of the lists given, without comments, comma-separated
packages() {
	sed 's/#.*//' "$@" | tr -s ' \t\n' '\n' | grep . | paste -sd,
}

step "edaha $VERSION, Debian $SUITE $ARCH from $MIRROR, SOURCE_DATE_EPOCH=$SOURCE_DATE_EPOCH"

# --- 1. edaha's package, built in a chroot of the same Debian ------------------------------
# The build packages are tools/deps.sh's BUILD_PKGS (one list for the project): the -dev
# packages for ARCH, the tools for this machine; a cross compiler when ARCH is not ours.
# dpkg-buildpackage checks them against debian/control's Build-Depends.
# shellcheck source=../tools/deps.sh
. "$REPO/tools/deps.sh"
build_pkgs=(dpkg-dev debhelper build-essential)
for p in $BUILD_PKGS; do
	case $p in
	*-dev) [ "$ARCH" = "$HOST_ARCH" ] && build_pkgs+=("$p") || build_pkgs+=("$p:$ARCH") ;;
	gcc | meson | ninja-build | pkg-config) build_pkgs+=("$p") ;;
	*) ;; # runtime and test packages (Mesa's drivers, the font): not needed to build
	esac
done
cross="" profiles=""
if [ "$ARCH" != "$HOST_ARCH" ]; then
	# crossbuild-essential-ARCH: the cross compilers (meson's debcrossgen, which writes
	# debhelper's cross file, wants gcc and g++); pkgconf:ARCH is the
	# pkg-config wrapper (aarch64-linux-gnu-pkg-config) for ARCH's .pc files; no tests cross-run
	build_pkgs+=("crossbuild-essential-$ARCH" "pkgconf:$ARCH")
	cross=" (cross-compiled for $ARCH)" profiles="-Pcross,nocheck"
fi
# tracked files as they are in the working tree (so a local change is built); the
# manifest says "-dirty" then
git -C "$REPO" ls-files -z | tar -C "$REPO" --null -T - -cf "$WORK/src.tar"
# debian/rules configures with every kiosk feature enabled; the .deb lands in /src
cat > "$WORK/build-edaha.sh" <<EOF
set -e
mkdir -p /src/edaha && tar -C /src/edaha -xf /tmp/src.tar
cd /src/edaha
DEB_BUILD_OPTIONS=${profiles:+nocheck} dpkg-buildpackage -b -us -uc -a $ARCH $profiles >/tmp/build.log 2>&1 || { tail -40 /tmp/build.log; exit 1; }
grep -A6 "^  Features" /tmp/build.log
EOF
deb=edaha_$(dpkg-parsechangelog -l "$REPO/debian/changelog" -S Version)_$ARCH.deb
step "building $deb in a $SUITE $HOST_ARCH chroot$cross"
mapfile -t cache_opts < <(apt_cache "$CACHE/apt-build-$HOST_ARCH")
# shellcheck disable=SC2016
mmdebstrap --variant=apt --architectures="$HOST_ARCH$([ "$ARCH" != "$HOST_ARCH" ] && echo ",$ARCH")" \
	--include="$(IFS=,; echo "${build_pkgs[*]}")" "${APTOPTS[@]}" \
	"${cache_opts[@]}" \
	--customize-hook='cp "$WORK/src.tar" "$WORK/build-edaha.sh" "$1/tmp/"' \
	--customize-hook='chroot "$1" sh /tmp/build-edaha.sh' \
	--customize-hook="copy-out /src/$deb $WORK/" \
	"$SUITE" /dev/null "${SOURCES[@]}" 2> >(grep -v '^I: ' >&2)
[ -f "$WORK/$deb" ] || die "dpkg-buildpackage made no $deb"
dpkg-deb -f "$WORK/$deb" Package Version Architecture Installed-Size | paste -sd' ' | sed 's/^/build: /'
rm -f "$OUT"/edaha_*.deb
cp "$WORK/$deb" "$OUT/"
if [ "${PACKAGE_ONLY:-0}" = 1 ]; then
	step "done: $OUT/$deb"
	exit 0
fi

# --- 2. the image's root filesystem -------------------------------------------------------
step "making the $ARCH root filesystem"
ROOT=$WORK/rootfs
wrap=()
[ "$ARCH" != "$HOST_ARCH" ] && wrap=("$HERE/foreign.sh" "$ARCH")
mapfile -t cache_opts < <(apt_cache "$CACHE/apt-$ARCH")
# no manuals, info pages, translations or documentation on a kiosk; the licences stay
slim=()
for p in /usr/share/man/\* /usr/share/info/\* /usr/share/locale/\* /usr/share/doc/\*; do
	slim+=("--dpkgopt=path-exclude=$p")
done
slim+=("--dpkgopt=path-include=/usr/share/doc/*/copyright" "--dpkgopt=path-include=/usr/share/locale/locale.alias")
# shellcheck disable=SC2016
"${wrap[@]}" mmdebstrap --variant=minbase --architectures="$ARCH" \
	--include="$(packages "$HERE/packages-common.txt" "$HERE/packages-$ARCH.txt")" \
	"${APTOPTS[@]}" "${cache_opts[@]}" "${slim[@]}" \
	--essential-hook='mkdir -p "$1/boot/firmware"' \
	--include="$WORK/$deb" --hook-dir=/usr/share/mmdebstrap/hooks/file-mirror-automount \
	--customize-hook="$HERE/customize.sh" \
	"$SUITE" "$ROOT" "${SOURCES[@]}" 2> >(grep -v '^I: ' >&2)

# what is in the image, for the record
dpkg-query --admindir="$ROOT/var/lib/dpkg" -W -f '${Package}\t${Version}\t${Architecture}\n' \
	> "$WORK/packages.tsv"
# every file's time stamp at most SOURCE_DATE_EPOCH (what the packages' scripts wrote)
find "$ROOT" -xdev -newermt "@$SOURCE_DATE_EPOCH" -print0 |
	xargs -0r touch --no-dereference --date="@$SOURCE_DATE_EPOCH"

# --- 3. the disk image ----------------------------------------------------------------
# a UUID that is the same for the same inputs
uuid() { sha256sum <<<"$1 $SOURCE_DATE_EPOCH" | sed -E 's/^(.{8})(.{4}).(.{3}).(.{3})(.{12}).*/\1-\2-4\3-a\4-\5/'; }
used_mb=$(du -sm --apparent-size "$ROOT" | cut -f1)
root_mb=${IMAGE_SIZE_MB:-$((used_mb * 11 / 10 + 512))}
mkroot() { # file: an ext4 filesystem of ROOT, labelled edaha-root
	local inodes
	inodes=$(($(find "$ROOT" -xdev | wc -l) * 2 + 65536))
	rm -f "$1"
	E2FSPROGS_FAKE_TIME=$SOURCE_DATE_EPOCH mkfs.ext4 -q -F -t ext4 -L edaha-root \
		-U "$(uuid "root $ARCH")" -E "hash_seed=$(uuid "hash $ARCH"),lazy_itable_init=0" \
		-N "$inodes" -d "$ROOT" "$1" "${root_mb}M" >/dev/null || die "mkfs.ext4 -d failed"
	# mkfs.ext4 -d copies each file's change time (ctime), which no one can set on this
	# machine's files, and its access time, which reading the directories here changed:
	# both SOURCE_DATE_EPOCH in the image, every inode by its path (debugfs leaves the
	# superblock's write time alone with the fake time)
	local path errors
	find "$ROOT" -xdev -printf '%P\0' | while IFS= read -r -d '' path; do
		case $path in *'"'* | *$'\n'*) die "a path debugfs cannot name: $path" ;; esac
		printf 'sif "/%s" ctime @%s\nsif "/%s" atime @%s\n' "$path" "$SOURCE_DATE_EPOCH" "$path" "$SOURCE_DATE_EPOCH"
	done > "$WORK/ctime.debugfs"
	errors=$(E2FSPROGS_FAKE_TIME=$SOURCE_DATE_EPOCH debugfs -w -f "$WORK/ctime.debugfs" "$1" 2>&1 >/dev/null | grep -v '^debugfs [0-9.]* (' || true)
	[ -z "$errors" ] || die "debugfs could not set the change times: $(head -5 <<<"$errors")"
	e2fsck -fn "$1" >/dev/null 2>&1 || die "the root filesystem does not pass e2fsck -fn"
}
rm -f "$OUT"/{root.img,disk.img,vmlinuz,initrd.img,cmdline.txt,manifest.txt,SHA256SUMS,reference-*.png}
kver=$(ls "$ROOT/lib/modules" | sort -V | tail -1)
if [ "$ARCH" = amd64 ]; then
	step "root.img (${root_mb} MiB ext4, ${used_mb} MiB used)"
	cp "$ROOT/boot/vmlinuz-$kver" "$OUT/vmlinuz"
	cp "$ROOT/boot/initrd.img-$kver" "$OUT/initrd.img"
	cp "$WORK/cmdline.txt" "$OUT/cmdline.txt"
	# the image does not need /boot's copy of what QEMU is given
	mkroot "$OUT/root.img"
	images=(root.img vmlinuz initrd.img)
else
	step "disk.img (FAT boot + ${root_mb} MiB ext4, ${used_mb} MiB used)"
	boot_mb=256
	[ -f "$ROOT/boot/firmware/config.txt" ] || die "raspi-firmware put no config.txt on /boot/firmware"
	# mkfs.vfat takes its volume id and times from the clock unless told (--invariant,
	# then -i: the id from the inputs)
	vol=$(uuid "boot $ARCH" | cut -c1-8)
	rm -f "$WORK/boot.vfat"
	mkfs.vfat -F 32 -n EDAHA-BOOT --invariant -i "$vol" -C "$WORK/boot.vfat" $((boot_mb * 1024)) >/dev/null
	(cd "$ROOT/boot/firmware" && find . -mindepth 1 -maxdepth 1 -printf '%P\0' | sort -z |
		xargs -0 sh -c 'mcopy -i "$0" -s -m -Q "$@" ::/' "$WORK/boot.vfat") ||
		die "mcopy to the boot partition failed"
	find "$ROOT/boot/firmware" -mindepth 1 -delete
	mkroot "$WORK/root.ext4"
	# MBR: the Pi's firmware reads the first FAT partition; 4 MiB before it
	start=8192 boot_sectors=$((boot_mb * 2048))
	root_start=$((start + boot_sectors))
	rm -f "$OUT/disk.img"
	truncate -s $(((root_start + root_mb * 2048) * 512)) "$OUT/disk.img"
	sfdisk -q "$OUT/disk.img" <<EOF
label: dos
label-id: 0x$vol
start=$start, size=$boot_sectors, type=c, bootable
start=$root_start, type=83
EOF
	dd if="$WORK/boot.vfat" of="$OUT/disk.img" bs=512 seek=$start conv=notrunc,sparse status=none
	dd if="$WORK/root.ext4" of="$OUT/disk.img" bs=512 seek=$root_start conv=notrunc,sparse status=none
	images=(disk.img)
	# what raspi-firmware wrote to the boot partition's cmdline.txt, for boot-test.sh
	cp "$WORK/cmdline.txt" "$OUT/cmdline.txt"
fi
cp "$WORK/reference-1280x800.png" "$OUT/"

{
	echo "# edaha kiosk image: Debian $SUITE $ARCH"
	echo "# edaha $VERSION"
	echo "# mirror $MIRROR, security $SECURITY_MIRROR"
	echo "# SOURCE_DATE_EPOCH=$SOURCE_DATE_EPOCH ($(date -u -d "@$SOURCE_DATE_EPOCH" +%FT%TZ))"
	echo "# kernel $kver"
	echo "# package	version	architecture"
	cat "$WORK/packages.tsv"
} > "$OUT/manifest.txt"
(cd "$OUT" && sha256sum "${images[@]}" "$deb" cmdline.txt manifest.txt reference-1280x800.png > SHA256SUMS)
step "done: $OUT ($(cd "$OUT" && du -sh --apparent-size "${images[@]}" | awk '{printf "%s%s %s", sep, $2, $1; sep=", "}'); $(wc -l < "$WORK/packages.tsv") packages)"

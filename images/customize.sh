#!/bin/sh
# mmdebstrap --customize-hook of images/build.sh: makes the Debian root filesystem $1 (edaha's
# package already installed into it, debian/) a kiosk that boots straight into edaha.
# Environment from build.sh: ARCH, HERE (images/), WORK (where the reference render and
# the kernel command line go), SOURCE_DATE_EPOCH.
set -eu
root=$1
: "${ARCH:?}" "${HERE:?}" "${WORK:?}"
in_root() { chroot "$root" "$@"; }
# the language of the image's configuration, for the reference render below
lang=$(sed -n 's/^language: *\([a-z]*\).*/\1/p' "$HERE/edaha-$ARCH.conf")

# shellcheck disable=SC2016 # dpkg-query's own ${Status}
in_root dpkg-query -W -f='${Status}\n' edaha | grep -qx 'install ok installed' ||
	{ echo "customize: the edaha package is not installed" >&2; exit 1; }
[ -x "$root/usr/bin/edaha" ] || { echo "customize: no /usr/bin/edaha in the root" >&2; exit 1; }
for unit in edaha.service edaha-usb.socket edaha-usb@.service; do
	[ -f "$root/lib/systemd/system/$unit" ] ||
		{ echo "customize: the package installed no $unit" >&2; exit 1; }
done
# the viewer every saved tree-NNNN.html carries (libjs-three, docs/page.md)
for js in three.min.js examples/js/loaders/GLTFLoader.js examples/js/controls/OrbitControls.js; do
	[ -f "$root/usr/share/javascript/three/$js" ] ||
		{ echo "customize: no $js (libjs-three): saves would carry no page" >&2; exit 1; }
done

# --- who and where ---
echo edaha > "$root/etc/hostname"
printf '127.0.0.1\tlocalhost\n127.0.1.1\tedaha\n::1\tlocalhost ip6-localhost ip6-loopback\n' \
	> "$root/etc/hosts"
# the build machine's, and the kiosk has no network
rm -f "$root/etc/resolv.conf"
# empty: every device writes its own at its first boot, and no first-boot presets run
# (machine-id(5)), so the units enabled here stay as they are
: > "$root/etc/machine-id"
rm -f "$root/var/lib/dbus/machine-id"

# --- filesystems: labels, so an SD card or a USB disk boots alike ---
{
	echo "# <file system> <mount point> <type> <options> <dump> <pass>"
	echo "LABEL=edaha-root / ext4 defaults,noatime,errors=remount-ro 0 1"
	[ "$ARCH" = arm64 ] && echo "LABEL=EDAHA-BOOT /boot/firmware vfat defaults,noatime,umask=0077 0 2"
} > "$root/etc/fstab"

# --- the kiosk's configuration (docs/config.md): the package's conffile is this
# directory's edaha-ARCH.conf (debian/rules), unchanged ---
cmp -s "$HERE/edaha-$ARCH.conf" "$root/etc/edaha/edaha.conf" ||
	{ echo "customize: /etc/edaha/edaha.conf is not images/edaha-$ARCH.conf" >&2; exit 1; }

# --- users: the kiosk's own, made by the package's postinst (systemd/edaha.sysusers,
# edaha.tmpfiles); nobody logs in ---
in_root getent passwd edaha >/dev/null || { echo "customize: no user edaha" >&2; exit 1; }
[ -d "$root/var/lib/edaha/archive" ] || { echo "customize: no /var/lib/edaha/archive" >&2; exit 1; }
# root's password is locked: no login on the serial console or anywhere else. To look
# inside, take out the SD card (README.md).
in_root usermod --lock root
in_root passwd --status root | grep -q ' L ' || { echo "customize: root is not locked" >&2; exit 1; }

# --- boot straight into the kiosk ---
in_root systemctl set-default multi-user.target
in_root systemctl enable edaha.service seatd.service
# the export button's USB sticks: edaha-usb-helper, one per connection (docs/usb.md)
in_root systemctl enable edaha-usb.socket
# tty1 is the kiosk's: no login prompt there, ever (edaha.service also Conflicts= with it;
# masked, as nothing may start it first). logind (for the power button: a clean
# shutdown) spawns no login on any other VT either, and keeps none in reserve.
in_root systemctl mask getty@tty1.service
mkdir -p "$root/etc/systemd/logind.conf.d"
cat > "$root/etc/systemd/logind.conf.d/edaha-image.conf" <<'EOF'
[Login]
NAutoVTs=0
ReserveVT=0
HandlePowerKey=poweroff
EOF
# the journal survives a reboot (what happened before the kiosk went wrong), kept small
mkdir -p "$root/etc/systemd/journald.conf.d" "$root/var/log/journal"
cat > "$root/etc/systemd/journald.conf.d/edaha-image.conf" <<'EOF'
[Journal]
Storage=persistent
SystemMaxUse=64M
EOF

# --- the kernel's command line ---
# quiet, no cursor blinking before the kiosk's first frame; the root by its label
cmdline="root=LABEL=edaha-root ro rootwait quiet loglevel=3 vt.global_cursor_default=0"
if [ "$ARCH" = amd64 ]; then
	# the QEMU image: boot messages and the journal's console on the serial port too
	echo "$cmdline console=tty0 console=ttyS0,115200" > "$WORK/cmdline.txt"
else
	# raspi-firmware writes config.txt and cmdline.txt on /boot/firmware from these when a
	# kernel or initrd is installed; its hook ran before them, so it runs again. Its own
	# checks look at the machine it runs on (the build machine here), so say for the Pi 4:
	# CMA=0 leaves out cma=, as it does on a Pi 4 (the device tree's pool is used);
	# consoles: boot messages on the header's UART (ttyS1, for a technician's cable) and
	# the screen (tty0, last: the console). Debian's kernel drives the display with vc4
	# (HDMI) and v3d (GL) from its upstream device trees: no dtoverlay= needed or shipped.
	cat > "$root/etc/default/raspi-firmware" <<EOF
# edaha image (images/customize.sh); the keys: /usr/share/doc/raspi-firmware and
# the package's own copy of this file
ROOTPART=LABEL=edaha-root
CONSOLES="ttyS1,115200 tty0"
CMA=0
KERNEL_ARCH=arm64
EOF
	# raspi-firmware puts "root=... rw" before these; "ro" lets systemd check the root
	# filesystem before remounting it read-write (fstab)
	echo "ro quiet loglevel=3 vt.global_cursor_default=0" > "$root/etc/default/raspi-extra-cmdline"
	rm -f "$root/etc/default/raspi-firmware-custom"
	in_root env DEB_MAINT_PARAMS=configure /etc/kernel/postinst.d/z50-raspi-firmware
	grep -q 'root=LABEL=edaha-root' "$root/boot/firmware/cmdline.txt" ||
		{ echo "customize: raspi-firmware wrote no cmdline.txt for LABEL=edaha-root" >&2; exit 1; }
	cp "$root/boot/firmware/cmdline.txt" "$WORK/cmdline.txt"
fi

# --- a reference picture: the image's own edaha, libraries and font, drawing the empty
# kiosk headlessly at QEMU's 1280x800 (images/boot-test.sh compares the screen with it) ---
rm -rf "$root/tmp/edaha-reference"
in_root env HOME=/tmp edaha --headless --size 1280x800 ${lang:+--lang "$lang"} \
	--out /tmp/edaha-reference > "$WORK/reference.log" 2>&1 ||
	{ cat "$WORK/reference.log" >&2; echo "customize: the headless render failed" >&2; exit 1; }
cp "$root/tmp/edaha-reference/screen.png" "$WORK/reference-1280x800.png"
rm -rf "$root/tmp/edaha-reference"

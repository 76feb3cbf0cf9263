#!/bin/bash
# Boots a kiosk image that images/build.sh made, in QEMU, and checks that it comes up as
# the kiosk: systemd starts edaha.service by itself, edaha reports its first
# frame on screen (READY to systemd), and the screen QEMU shows is edaha's empty canvas (the
# image's own headless render, reference-1280x800.png) rather than a console or a black
# screen. Then a FAT USB stick is plugged in and the pointer clicks Save: the tree must be
# on the stick (read back with mtools once the guest is off). Last a power-off, which the
# kiosk must come through cleanly.
#
#   images/boot-test.sh [-t SECONDS] OUT
#     OUT  build.sh's output directory; the serial log and the screenshot go to
#          OUT/boot-test/. amd64 (root.img, vmlinuz, initrd.img, cmdline.txt): a PC
#          (qemu-system-x86_64, bochs-display). arm64 (disk.img): the Raspberry Pi image's
#          own disk on QEMU's "virt" board (qemu-system-aarch64, cortex-a72, virtio-gpu),
#          its kernel and initrd taken from the boot partition: everything but the Pi's
#          firmware, device tree and vc4 display (and its GPIO chip: the buttons are
#          warnings there).
#     -t   time limit for the boot to the first frame (default 300: TCG on 2 cores)
#   Environment: IMGCMP (tests/tools/imgcmp; default: built from this checkout under
#   IMAGE_CACHE, default /tmp/edaha-image-cache), VM_LOCK (default /tmp/edaha-vm.lock, the
#   lock tests/system/vm.sh takes too: one guest at a time on this machine).
#
# The image is not changed (QEMU writes to a snapshot). The guest's kernel command line is
# the image's cmdline.txt plus systemd.journald.forward_to_console=1: the journal (edaha's
# stderr among it) comes out on the serial port. TCG, not KVM (a nested KVM guest hangs
# here); the display at 1280x800. Exit 0 when every check holds, 1 when one fails, 77
# when QEMU is missing.
# Packages: qemu-system-x86 (amd64), qemu-system-arm fdisk (arm64), mtools dosfstools; for IMGCMP,
# tools/deps.sh's BUILD_PKGS.
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
REPO=$(cd "$HERE/.." && pwd)
limit=300
while getopts "t:" opt; do
	case $opt in
	t) limit=$OPTARG ;;
	*) exit 2 ;;
	esac
done
shift $((OPTIND - 1))
[ $# -eq 1 ] || { echo "usage: images/boot-test.sh [-t SECONDS] OUT" >&2; exit 2; }
OUT=$(realpath "$1")
fail() { echo "boot-test: FAIL: $*" >&2; exit 1; }
skip() { echo "boot-test: SKIP: $*"; exit 77; }
if [ -r "$OUT/disk.img" ]; then
	arch=arm64
	need=(disk.img cmdline.txt reference-1280x800.png)
else
	arch=amd64
	need=(root.img vmlinuz initrd.img cmdline.txt reference-1280x800.png)
fi
for f in "${need[@]}"; do
	[ -r "$OUT/$f" ] || fail "no $OUT/$f (images/build.sh amd64|arm64 $1 makes it)"
done
if [ $arch = amd64 ]; then
	command -v qemu-system-x86_64 >/dev/null || skip "no qemu-system-x86_64 (apt-get install qemu-system-x86)"
else
	command -v qemu-system-aarch64 >/dev/null || skip "no qemu-system-aarch64 (apt-get install qemu-system-arm)"
	command -v sfdisk >/dev/null || skip "no sfdisk (apt-get install fdisk)"
fi
# the USB stick: made, and read back
command -v mcopy >/dev/null || skip "no mcopy (apt-get install mtools)"
command -v mkfs.vfat >/dev/null || skip "no mkfs.vfat (apt-get install dosfstools)"

if [ -z "${IMGCMP:-}" ]; then
	# one build per checkout: a build directory is tied to the source tree it was made from
	b=${IMAGE_CACHE:-/tmp/edaha-image-cache}/imgcmp-build-$(printf %s "$REPO" | sha1sum | cut -c1-12)
	[ -f "$b/build.ninja" ] || { rm -rf "$b" && meson setup "$b" "$REPO" >/dev/null; } ||
		fail "cannot configure $REPO to build imgcmp (tools/deps.sh's BUILD_PKGS)"
	meson compile -C "$b" tests/tools/imgcmp >/dev/null || fail "cannot build imgcmp"
	IMGCMP=$b/tests/tools/imgcmp
fi

RES=$OUT/boot-test
rm -rf "$RES"
mkdir -p "$RES"
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-boot-test.XXXXXX")
qemu_pid=""
cleanup() {
	[ -n "$qemu_pid" ] && kill "$qemu_pid" 2>/dev/null
	rm -rf "$T"
}
trap cleanup EXIT
mkfifo "$T/qmp.in" "$T/qmp.out"
log=$RES/serial.log
: > "$log"

# one guest at a time on this machine, whoever starts it
exec 9>"${VM_LOCK:-/tmp/edaha-vm.lock}"
flock 9
start=$(date +%s%N)
since() { # seconds since QEMU started, to a tenth
	local ds=$((($(date +%s%N) - start) / 100000000))
	echo "$((ds / 10)).$((ds % 10))"
}
case $arch in
amd64)
	# shellcheck disable=SC2054 # commas within QEMU's options
	qemu=(qemu-system-x86_64 -cpu max -kernel "$OUT/vmlinuz" -initrd "$OUT/initrd.img"
		-append "$(cat "$OUT/cmdline.txt") systemd.journald.forward_to_console=1 panic=-1"
		-drive "file=$OUT/root.img,format=raw,if=virtio,snapshot=on"
		-device bochs-display,xres=1280,yres=800)
	;;
arm64)
	# the kernel and initrd the Pi's firmware would load, from the first partition
	boot=$(($(sfdisk --dump "$OUT/disk.img" | sed -n 's/^[^ ]*1 : start= *\([0-9]*\),.*/\1/p') * 512))
	[ "$boot" -gt 0 ] || fail "no boot partition in $OUT/disk.img"
	kernel=$(mdir -b -i "$OUT/disk.img@@$boot" ::/ | sed -n 's|^::/\(vmlinuz-.*\)|\1|p' | sort -V | tail -1)
	[ -n "$kernel" ] || fail "no vmlinuz-* on $OUT/disk.img's boot partition"
	mcopy -n -i "$OUT/disk.img@@$boot" "::/$kernel" "::/initrd.img-${kernel#vmlinuz-}" "$T/" ||
		fail "cannot read the kernel and initrd from the boot partition"
	# the Pi's command line; the serial console is the board's PL011 here
	# shellcheck disable=SC2054
	qemu=(qemu-system-aarch64 -M virt -cpu cortex-a72
		-kernel "$T/$kernel" -initrd "$T/initrd.img-${kernel#vmlinuz-}"
		-append "$(cat "$OUT/cmdline.txt") console=ttyAMA0 systemd.journald.forward_to_console=1 panic=-1"
		-drive "file=$OUT/disk.img,format=raw,if=virtio,snapshot=on"
		-device virtio-gpu-pci,xres=1280,yres=800)
	;;
esac
# a USB controller for the stick, and a pointer that clicks where it is told (absolute)
"${qemu[@]}" -accel tcg,thread=multi -smp 2 -m 2048 -nodefaults -no-reboot -display none \
	-device virtio-rng-pci -device qemu-xhci,id=xhci -device virtio-tablet-pci -serial "file:$log" \
	-chardev "pipe,id=qmp,path=$T/qmp" -mon chardev=qmp,mode=control &
qemu_pid=$!
exec 3<>"$T/qmp.out" 4>"$T/qmp.in"

# QMP: a command, then its answer (events in between are skipped)
qmp() {
	local line
	echo "$1" >&4
	while read -r -t 30 -u 3 line; do
		case $line in *'"return"'* | *'"error"'*) echo "$line"; return 0 ;; esac
	done
	return 1
}
read -r -t 30 -u 3 _ || fail "QEMU's QMP said nothing"
qmp '{"execute":"qmp_capabilities"}' >/dev/null || fail "QMP capabilities"

echo "boot-test: booting $OUT/${need[0]} ($arch, ${qemu[0]}, TCG, 2 CPUs, ${qemu[-1]%%,*} 1280x800; limit $limit s)"
first=""
while :; do
	# the serial console ends its lines with \r\n
	first=$(grep -m1 -a 'edaha: first frame on screen' "$log" | tr -d '\r' || true)
	[ -n "$first" ] && break
	kill -0 "$qemu_pid" 2>/dev/null || { tail -30 "$log" >&2; fail "QEMU ended before the kiosk's first frame"; }
	if grep -q -a 'edaha.service: Scheduled restart job' "$log"; then
		grep -a 'edaha' "$log" | tail -30 >&2
		fail "edaha.service failed and is being restarted"
	fi
	[ "$(since | cut -d. -f1)" -lt "$limit" ] ||
		{ tail -30 "$log" >&2; fail "no first frame within $limit s"; }
	sleep 1
done
at=$(since)
echo "boot-test: ${first#*edaha: } (guest), $at s after QEMU started"
# the first frame is on screen: what QEMU's display shows now
qmp "{\"execute\":\"screendump\",\"arguments\":{\"filename\":\"$RES/screen.png\",\"format\":\"png\"}}" |
	grep -q '"return"' || fail "QMP screendump"

ok=1
check() { # description, command...
	local what=$1; shift
	if "$@"; then echo "boot-test: ok: $what"; else echo "boot-test: FAIL: $what" >&2; ok=0; fi
}
# Multisampled edges are resolved by another path than the headless framebuffer's (as in
# tests/system/display.sh): a few hundred pixels differ; a console or a black screen would not
# fit
check "the screen is the kiosk's empty canvas (imgcmp against reference-1280x800.png)" \
	"$IMGCMP" --max-diff 64 --max-fraction 0.005 --diff "$RES/diff.png" \
	"$OUT/reference-1280x800.png" "$RES/screen.png"
sleep 2 # the journal's lines about the start are forwarded a moment later
check "systemd had edaha.service READY (Type=notify)" grep -q -a 'Started edaha.service' "$log"
check "edaha runs on the card through seatd" grep -q -a 'edaha: kiosk on /dev/dri/card0 .*libseat (seatd)' "$log"
check "edaha-usb.socket listens for the kiosk's USB sticks" grep -q -a 'Listening on edaha-usb.socket' "$log"
check "/etc/edaha/edaha.conf read without a word about it" \
	bash -c "! grep -a 'edaha.conf:[0-9]*:' '$log'"
check "no login prompt on tty1 (getty@tty1 never started)" bash -c "! grep -q -a 'Started getty@tty1' '$log'"
booted=$(grep -a -m1 -o 'Startup finished in .*' "$log" | tr -d '\r' || true)

# Save to a USB stick, as a visitor would: a FAT stick (no partition table, as many are) is
# plugged in, then the pointer clicks the Save button
wait_log() { # pattern seconds: the serial log has a line matching pattern within seconds
	local i
	for ((i = 0; i < $2; i++)); do
		grep -q -a -- "$1" "$log" && return 0
		kill -0 "$qemu_pid" 2>/dev/null || return 1
		sleep 1
	done
	return 1
}
click() { # x y on the 1280x800 screen: QMP's absolute axes run 0..32767
	local x=$(($1 * 32767 / 1279)) y=$(($2 * 32767 / 799)) e
	for e in "{\"type\":\"abs\",\"data\":{\"axis\":\"x\",\"value\":$x}},{\"type\":\"abs\",\"data\":{\"axis\":\"y\",\"value\":$y}}" \
		'{"type":"btn","data":{"down":true,"button":"left"}}' \
		'{"type":"btn","data":{"down":false,"button":"left"}}'; do
		qmp "{\"execute\":\"input-send-event\",\"arguments\":{\"events\":[$e]}}" | grep -q '"return"' || return 1
		sleep 0.5
	done
}
mkfs.vfat -n STICK -C "$T/stick.img" $((32 * 1024)) >/dev/null
qmp "{\"execute\":\"blockdev-add\",\"arguments\":{\"driver\":\"raw\",\"node-name\":\"stick\",\"file\":{\"driver\":\"file\",\"filename\":\"$T/stick.img\"}}}" |
	grep -q '"return"' || fail "QMP blockdev-add"
qmp '{"execute":"device_add","arguments":{"driver":"usb-storage","bus":"xhci.0","drive":"stick","id":"stick-dev","removable":true}}' |
	grep -q '"return"' || fail "QMP device_add usb-storage"
check "the kiosk found the stick (usb: ... (vfat) is ready)" wait_log 'usb: sd[a-z0-9]* (vfat) is ready' 120
# the Save button: the bottom one of the column on the right (src/core/layout.c) at 1280x800,
# as reference-1280x800.png shows it
click 1202 745 || fail "QMP input-send-event"
check "Save wrote the tree to the stick (usb: saved tree-0001)" wait_log 'usb: saved tree-0001' 180
saved=$(grep -a -m1 -o 'usb: saved tree-0001.*' "$log" | tr -d '\r' || true)

# power off, as pulling the plug politely would: edaha must stop on SIGTERM
qmp '{"execute":"system_powerdown"}' >/dev/null || fail "QMP system_powerdown"
for _ in $(seq 120); do kill -0 "$qemu_pid" 2>/dev/null || break; sleep 1; done
if kill -0 "$qemu_pid" 2>/dev/null; then
	echo "boot-test: FAIL: the guest did not power off within 120 s" >&2; ok=0
else
	qemu_pid=""
	check "edaha stopped cleanly at power-off" grep -q -a 'edaha: Terminated, stopping' "$log"
fi
# what the visitor takes home, read on this side with mtools
files=$(mdir -b -i "$T/stick.img" ::/edaha/ 2>/dev/null | sed 's|.*/||' | sort | tr '\n' ' ')
check "the stick holds edaha/tree-0001.{edaha,glb,mtl,obj,png} ($files)" \
	test "$files" = "tree-0001.edaha tree-0001.glb tree-0001.mtl tree-0001.obj tree-0001.png "
check "tree-0001.glb is glTF" bash -c "mtype -i '$T/stick.img' ::/edaha/tree-0001.glb | head -c4 | grep -q glTF"
failed=$(grep -a 'Failed to start\|failed with result\|Dependency failed' "$log" || true)
[ -z "$failed" ] || { echo "boot-test: units that failed:"; echo "$failed"; }
check "no unit failed" test -z "$failed"

stopped=$(since)
echo "boot-test: ${booted:+systemd: $booted; }first frame $at s after QEMU started, off at $stopped s"
[ -n "$saved" ] && echo "boot-test: $saved"
echo "boot-test: serial log $log, screenshot $RES/screen.png"
[ $ok = 1 ] || fail "the image did not come up as the kiosk (above)"
echo "boot-test: PASS"

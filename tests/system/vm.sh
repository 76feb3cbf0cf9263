#!/bin/bash
# Runs a command in a throw-away QEMU guest: Debian's own kernel (linux-image-amd64) with a
# busybox initramfs, this machine's root filesystem shared read-only over 9p under a tmpfs
# overlay (so host-built binaries and their libraries run unchanged), a bochs-display for
# KMS and a writable results folder. TCG, not KVM: a nested KVM guest hangs in early boot.
#
#   vm.sh [-t SECONDS] [-o DIR] [-g bochs|virtio|none] [-s WxH] [-v SOCKET] [-r DIR]
#         [-i sh|systemd] [-u] [-q SOCKET] -- COMMAND [ARGS...]
#     -t  time limit for the whole VM (default 120)
#     -o  host DIR mounted read-write at /out in the guest
#     -g  display device (default bochs: bochs-display)
#     -s  the display's preferred mode (default 1280x800)
#     -v  a VNC server on the unix SOCKET, whose clients may resize a virtio display
#     -r  host DIR laid over the root filesystem, under the tmpfs (e.g. a `meson install
#         --destdir` tree: the guest boots with it installed)
#     -i  PID 1: sh (default: COMMAND runs as soon as udev has settled) or systemd
#         (systemd boots edaha-vmtest.target: sysinit with udev, journald, sysusers and
#         tmpfiles, then COMMAND as the unit edaha-vmtest.service, output on the console;
#         VM_APPEND adds to the kernel command line)
#     -u  an xHCI USB controller (id xhci) to hot-plug USB sticks on (usb-storage,
#         bus=xhci.0) through QMP
#     -q  QEMU's QMP monitor on the unix SOCKET (qmp.py: plug and pull sticks)
#   Environment: KVER (kernel version, default the newest in /lib/modules),
#   VM_CACHE (where the initramfs is kept, default /tmp/edaha-vm-cache), VM_VERBOSE=1,
#   VM_LOCK (the lock file that lets one guest run at a time, default /tmp/edaha-vm.lock).
#
# The guest sees the host's files where the host has them, /tmp and /home included, with
# either PID 1: a checkout and its build may be anywhere (under systemd, tmp.mount is
# masked and tmpfiles leaves /tmp as it is; units with PrivateTmp= or ProtectHome= still
# get their own view). Writes stay in the guest's tmpfs.
# COMMAND runs as root with the caller's working directory; its exit status becomes
# ours. 77 (meson's "skipped") when QEMU or the kernel is missing, 125 when the guest
# never reported one (boot failure, time limit).
# Packages: qemu-system-x86 linux-image-amd64 busybox-static cpio kmod udev.
set -euo pipefail

limit=120 out="" gpu=bochs size=1280x800 vnc="" extra="" init=sh usb="" qmp=""
while getopts "t:o:g:s:v:r:i:uq:" opt; do
	case $opt in
	t) limit=$OPTARG ;;
	o) mkdir -p "$OPTARG"; out=$(realpath "$OPTARG") ;;
	g) gpu=$OPTARG ;;
	s) size=$OPTARG ;;
	v) vnc=$OPTARG ;;
	r) extra=$(realpath "$OPTARG") ;;
	i) init=$OPTARG ;;
	u) usb=1 ;;
	q) qmp=$OPTARG ;;
	*) exit 2 ;;
	esac
done
shift $((OPTIND - 1))
[ "${1:-}" = "--" ] && shift
[ $# -ge 1 ] || { echo "usage: vm.sh [-t SECONDS] [-o DIR] [-g bochs|virtio|none] [-s WxH] [-v SOCKET] -- COMMAND..." >&2; exit 2; }
case $size in [1-9]*x[1-9]*) ;; *) echo "vm: bad size $size" >&2; exit 2 ;; esac
case $init in sh | systemd) ;; *) echo "vm: unknown init $init" >&2; exit 2 ;; esac

skip() { echo "vm: SKIP: $*"; exit 77; }
command -v qemu-system-x86_64 >/dev/null || skip "no qemu-system-x86_64 (apt-get install qemu-system-x86)"
[ -x /bin/busybox ] || skip "no /bin/busybox (apt-get install busybox-static)"
command -v cpio >/dev/null || skip "no cpio"
kver=${KVER:-$(ls /lib/modules 2>/dev/null | sort -V | tail -1)}
kernel=/boot/vmlinuz-$kver
[ -n "$kver" ] && [ -r "$kernel" ] || skip "no readable kernel /boot/vmlinuz-* (apt-get install linux-image-amd64)"

cache=${VM_CACHE:-/tmp/edaha-vm-cache}/$kver
initrd=$cache/initrd.cpio.gz

# The initramfs only loads what reaching the host root needs (9p over virtio, overlay),
# mounts it and switches to it; /job/guest.sh then does the rest on the real root.
build_initrd() {
	local root=$cache/root m
	rm -rf "$root"
	mkdir -p "$root"/{bin,dev,proc,sys,host,newroot,job,lib/modules}
	cp /bin/busybox "$root/bin/busybox"
	for m in sh mount mkdir insmod switch_root cat grep rm; do ln -s busybox "$root/bin/$m"; done
	for m in virtio_pci 9pnet_virtio 9p overlay; do modprobe -S "$kver" --show-depends $m; done |
		awk '$1 == "insmod" && !seen[$2]++ { print $2 }' > "$cache/modules"
	while read -r m; do
		cp "$m" "$root/lib/modules/"
		echo "insmod /lib/modules/$(basename "$m")"
	done < "$cache/modules" > "$root/modules.sh"
	cat > "$root/init" <<'EOF'
#!/bin/sh
mount -t proc proc /proc; mount -t sysfs sys /sys; mount -t devtmpfs dev /dev
cmdline=$(cat /proc/cmdline)
. /modules.sh
mount -t 9p -o trans=virtio,version=9p2000.L,ro,cache=loose hostroot /host
mount -t 9p -o trans=virtio,version=9p2000.L,rw job /job
lower=/host
if echo "$cmdline" | grep -q edaha.extra; then
	mkdir -p /extra && mount -t 9p -o trans=virtio,version=9p2000.L,ro,cache=loose extra /extra
	lower=/extra:/host
fi
mkdir -p /rw && mount -t tmpfs -o size=1G tmpfs /rw && mkdir -p /rw/upper /rw/work
mount -t overlay -o lowerdir=$lower,upperdir=/rw/upper,workdir=/rw/work overlay /newroot
for d in proc sys dev job; do mkdir -p /newroot/$d; mount -o move /$d /newroot/$d; done
mount -t tmpfs -o mode=0755 tmpfs /newroot/run
if echo "$cmdline" | grep -q edaha.init=systemd; then
	# the host may be a container: systemd must not believe it runs in one
	rm -f /newroot/.dockerenv /newroot/run/.containerenv
	# the host's /tmp stays in view, as under sh: a checkout or a build there is what
	# COMMAND runs. tmpfiles' tmp.conf would empty it at boot (file by file over 9p, and
	# the checkout with it); this one only makes sure it is there
	mkdir -p /newroot/etc/tmpfiles.d
	echo 'd /tmp 1777 root root -' > /newroot/etc/tmpfiles.d/tmp.conf
	# units in /run/systemd/system: systemd keeps this /run
	mkdir -p /newroot/run/systemd/system
	cat /newroot/job/edaha-vmtest.target > /newroot/run/systemd/system/edaha-vmtest.target
	cat /newroot/job/edaha-vmtest.service > /newroot/run/systemd/system/edaha-vmtest.service
	exec switch_root /newroot /lib/systemd/systemd
fi
exec switch_root /newroot /bin/sh /job/guest.sh
EOF
	chmod +x "$root/init"
	(cd "$root" && find . | cpio -o -H newc --quiet | gzip -1) > "$initrd.tmp"
	mv "$initrd.tmp" "$initrd"
}
mkdir -p "$cache"
# rebuilt when this script changes, so a fix to init reaches every later run; one
# builder at a time, whatever lock the guests take
exec 8>"$cache/build.lock"
flock 8
{ [ -s "$initrd" ] && [ "$initrd" -nt "$0" ]; } || build_initrd
exec 8>&-
# One guest at a time on this machine, whoever starts it (meson, a developer, a second
# checkout): two TCG guests on a small machine starve each other (on two cores, with the
# rest of tools/test beside them, system-display took 368 s, not 138).
exec 9>"${VM_LOCK:-/tmp/edaha-vm.lock}"
flock 9

job=$(mktemp -d /tmp/edaha-vm-job.XXXXXX)
trap 'rm -rf "$job"' EXIT
printf '%q ' "$@" > "$job/cmd"
printf 'OUT=%q\nCWD=%q\nVERBOSE=%q\nGPU=%q\nINIT=%q\n' "$out" "$PWD" "${VM_VERBOSE:-}" "$gpu" "$init" > "$job/env"
cat > "$job/guest.sh" <<'EOF'
#!/bin/sh
# PID 1 in the guest, on the overlay root
export PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root TERM=dumb
. /job/env
mkdir -p /dev/pts && mount -t devpts devpts /dev/pts
if [ -n "$OUT" ]; then mkdir -p /out && mount -t 9p -o trans=virtio,version=9p2000.L,rw out /out; fi
[ -n "$VERBOSE" ] && echo "vm: userspace up at $(cut -d' ' -f1 /proc/uptime) s"
# the display driver, loaded here: udev is not asked to go through every PCI device
case $GPU in bochs) modprobe bochs ;; virtio) modprobe virtio_gpu ;; esac
# udev fills in the device database libinput and Mesa's loader read (under systemd, its
# own udevd does, with the rules installed)
if [ "$INIT" = systemd ]; then
	udevadm settle -t 30
else
	/lib/systemd/systemd-udevd --daemon --resolve-names=never 2>/dev/null &&
		udevadm trigger --action=add --subsystem-match=input --subsystem-match=drm &&
		udevadm settle -t 10
fi
[ -n "$VERBOSE" ] && echo "vm: udev settled at $(cut -d' ' -f1 /proc/uptime) s"
cd "$CWD" && sh -c "$(cat /job/cmd)" < /dev/null
echo $? > /job/rc
sync
exec /bin/busybox poweroff -f
EOF

# systemd's way in: a target with sysinit and the command (guest.sh powers off when done)
cat > "$job/edaha-vmtest.target" <<'UNIT'
[Unit]
Description=edaha VM test
Requires=sysinit.target edaha-vmtest.service
After=sysinit.target edaha-vmtest.service
AllowIsolate=yes
UNIT
cat > "$job/edaha-vmtest.service" <<'UNIT'
[Unit]
Description=edaha VM test command
After=sysinit.target systemd-udev-trigger.service
[Service]
Type=oneshot
ExecStart=/bin/sh /job/guest.sh
StandardOutput=tty
StandardError=tty
TTYPath=/dev/ttyS0
TimeoutStartSec=infinity
UNIT
append="console=ttyS0 quiet loglevel=3 panic=-1 rdinit=/init"
[ -n "$extra" ] && append+=" edaha.extra"
[ "$init" = systemd ] && append+=" edaha.init=systemd systemd.unit=edaha-vmtest.target
 systemd.show_status=false systemd.firstboot=off systemd.mask=systemd-timesyncd.service
 systemd.mask=systemd-pstore.service systemd.mask=systemd-binfmt.service
 systemd.mask=systemd-repart.service systemd.mask=proc-sys-fs-binfmt_misc.automount
 systemd.mask=tmp.mount ${VM_APPEND:-}"
append=$(echo $append)

qemu=(qemu-system-x86_64 -accel tcg,thread=multi -cpu max -smp 2 -m 2048
	-nographic -no-reboot -nodefaults -serial stdio
	-kernel "$kernel" -initrd "$initrd"
	-append "$append"
	-fsdev local,id=hostroot,path=/,security_model=none,readonly=on,multidevs=remap
	-device virtio-9p-pci,fsdev=hostroot,mount_tag=hostroot
	-fsdev local,id=job,path="$job",security_model=none
	-device virtio-9p-pci,fsdev=job,mount_tag=job)
case $gpu in
bochs) qemu+=(-device "bochs-display,xres=${size%x*},yres=${size#*x}") ;;
virtio) qemu+=(-device "virtio-gpu-pci,xres=${size%x*},yres=${size#*x}") ;;
none) ;;
*) echo "vm: unknown display $gpu" >&2; exit 2 ;;
esac
if [ -n "$out" ]; then
	qemu+=(-fsdev local,id=out,path="$out",security_model=none -device virtio-9p-pci,fsdev=out,mount_tag=out)
fi
[ -n "$vnc" ] && qemu+=(-vnc "unix:$vnc")
[ -n "$usb" ] && qemu+=(-device qemu-xhci,id=xhci)
[ -n "$qmp" ] && qemu+=(-qmp "unix:$qmp,server=on,wait=off")
if [ -n "$extra" ]; then
	qemu+=(-fsdev local,id=extra,path="$extra",security_model=none,readonly=on,multidevs=remap
		-device virtio-9p-pci,fsdev=extra,mount_tag=extra)
fi
timeout "$limit" "${qemu[@]}" < /dev/null || echo "vm: qemu exited with status $?" >&2
rc=$(cat "$job/rc" 2>/dev/null || echo 125)
[ "$rc" = 125 ] && echo "vm: the guest reported no exit status (boot failure or time limit $limit s)" >&2
exit "$rc"

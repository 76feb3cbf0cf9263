#!/bin/sh
# The guest half of usb.sh, run by systemd (vm.sh -i systemd) on a root with edaha
# installed by meson: edaha-usb.socket and edaha.service started as at boot, a tree drawn
# with the virtual pen, then the host's commands, one file each (/out/cmd.N, answered by
# /out/ack.N), while the host plugs and pulls sticks through QMP:
#   export   presses the export button (gpio-sim line 3)
#   mounts   writes what is mounted under /run/edaha/media to /out/mounts.txt
#   readback-exfat  copies edaha/ of the exFAT stick in to /out/exfat/
#   stop     ends the session
# Writes to /out: edaha.log (the journal of the kiosk and the helper), status.txt,
# local/ (the copies in kiosk.export_dir), drawn (the tree is on screen).
#   usb_guest.sh UINPUT_PEN KMOD_DIR
pen=$1 kmod=$2
H=$(dirname "$0")
say() { echo "usb_guest: $*"; }

for m in uinput xhci_pci usb_storage sd_mod vfat exfat ext4 nls_cp437 nls_utf8 nls_iso8859_1; do
	modprobe $m || say "no module $m"
done
"$H/gpio_sim.sh" setup "$kmod" || exit 3
udevadm settle -t 30
journalctl -f -o cat -u edaha.service -u 'edaha-usb@*.service' > /out/edaha.log 2>&1 &
journal=$!
systemctl start edaha-usb.socket || say "edaha-usb.socket did not start"
systemctl start edaha.service || { say "edaha.service did not start"; systemctl status edaha --no-pager; }
export TABLET_ADDED="$H/tablet_added.sh /out/edaha.log"
UINPUT_PEN_WAIT_MS=0 "$pen" < "$H/usb.script" 2> /out/pen.err || say "uinput_pen failed"
touch /out/drawn

n=1
while :; do
	i=0
	while [ ! -f /out/cmd.$n ] && [ $i -lt 1500 ]; do sleep 0.2; i=$((i + 1)); done
	[ -f /out/cmd.$n ] || { say "no command $n from the host in 300 s"; break; }
	cmd=$(cat /out/cmd.$n)
	case $cmd in
	export)
		"$H/gpio_sim.sh" press 3
		sleep 0.3
		"$H/gpio_sim.sh" release 3
		;;
	mounts) grep ' /run/edaha/media/' /proc/1/mountinfo > /out/mounts.txt ;;
	readback-exfat)
		# no mtools for exFAT: the stick's edaha/ as this kernel reads it
		dev=$(blkid -t TYPE=exfat -o device | head -1)
		mkdir -p /mnt/exfat /out/exfat
		mount -o ro "$dev" /mnt/exfat && cp /mnt/exfat/edaha/* /out/exfat/
		ls -la /mnt/exfat/edaha > /out/exfat.ls 2>&1
		umount /mnt/exfat
		;;
	stop) touch /out/ack.$n; break ;;
	*) say "unknown command $cmd" ;;
	esac
	touch /out/ack.$n
	n=$((n + 1))
done

pid=$(systemctl show edaha.service -p MainPID --value)
systemctl show edaha.service -p ActiveState -p SubState -p NRestarts > /out/status.txt
echo "User=$(ps -o user= -p "$pid")" >> /out/status.txt
ls -l /run/edaha/usb.sock >> /out/status.txt 2>&1
mkdir -p /out/local && cp /var/lib/edaha/export/* /out/local/ 2>/dev/null
systemctl stop edaha.service
sleep 1
kill $journal
journalctl -o cat -u edaha.service -u 'edaha-usb@*.service' --no-pager > /out/edaha.log
exit 0

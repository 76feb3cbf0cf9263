#!/bin/sh
# In the VM, as root: the kiosk's buttons on a gpio-sim chip (configfs; the gpio-sim module
# built by build_kmods.sh when the kernel lacks it).
#   gpio_sim.sh setup KMOD_DIR   loads gpio-sim, makes chip "kiosk-buttons": lines 0..4 are
#                                btn-3d btn-clone btn-leaf btn-export btn-propagate, 5 and 6
#                                led-3d led-clone, 7 btn-grow, 8 btn-vine
#   gpio_sim.sh press N | release N   pulls button line N down (pressed, active-low) or up
#   gpio_sim.sh bounce N         press, release, press at once (a bouncing contact)
#   gpio_sim.sh value N          prints line N's value (an LED the kiosk drives)
set -e
C=/sys/kernel/config/gpio-sim/kiosk
sim() { echo "/sys/devices/platform/$(cat $C/dev_name)/$(cat $C/bank0/chip_name)/sim_gpio$1"; }
case $1 in
setup)
	[ -d /sys/kernel/config ] || modprobe configfs
	mountpoint -q /sys/kernel/config || mount -t configfs none /sys/kernel/config
	[ -d /sys/kernel/config/gpio-sim ] || modprobe gpio-sim 2>/dev/null ||
		insmod "$2/gpio-sim/gpio-sim-oot.ko"
	mkdir $C $C/bank0
	echo 9 > $C/bank0/num_lines
	echo kiosk-buttons > $C/bank0/label
	n=0
	for name in btn-3d btn-clone btn-leaf btn-export btn-propagate led-3d led-clone btn-grow btn-vine; do
		if [ "$name" != - ]; then mkdir $C/bank0/line$n; echo $name > $C/bank0/line$n/name; fi
		n=$((n + 1))
	done
	echo 1 > $C/live
	;;
press) echo pull-down > "$(sim "$2")/pull" ;;
bounce) p=$(sim "$2")/pull; echo pull-down >"$p"; echo pull-up >"$p"; echo pull-down >"$p" ;;
release) echo pull-up > "$(sim "$2")/pull" ;;
value) cat "$(sim "$2")/value" ;;
*) echo "usage: gpio_sim.sh setup KMOD_DIR | press N | release N | bounce N | value N" >&2; exit 2 ;;
esac

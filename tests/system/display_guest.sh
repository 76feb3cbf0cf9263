#!/bin/sh
# The guest half of display.sh, run inside the VM: display_guest.sh EDAHA SCANOUT FRAMES OUT
#  1. atomic: edaha --kiosk-frames FRAMES --screenshot OUT/atomic.png (a frame a vblank)
#  2. legacy: the same with EDAHA_DRM_LEGACY=1: OUT/legacy.png
#  3. turned: --config rotate90.conf (display.rotation 90), 2 frames: OUT/rotate90.png;
#     then idle, what the screen shows turned back: OUT/rotate90-screen.png
#  4. seatd runs; edaha as a kiosk, idle, through libseat (screen: OUT/idle-*.png). After
#     its first frame it must draw nothing until the display is unplugged and plugged
#     back (one frame) and the VT switched away (the console's picture) and back (one
#     frame); SIGTERM must end it cleanly (status 0).
# Each run's stderr goes to OUT/NAME.log, the steps of 3 and 4 to OUT/steps.log.
edaha=$1 scanout=$2 frames=$3 out=$4
here=$(dirname "$0")
conn=/sys/class/drm/card0-Virtual-1

"$edaha" --kiosk-frames "$frames" --screenshot "$out/atomic.png" 2>"$out/atomic.log" || exit $?
EDAHA_DRM_LEGACY=1 "$edaha" --kiosk-frames "$frames" --screenshot "$out/legacy.png" \
	2>"$out/legacy.log" || exit $?
"$edaha" --config "$here/rotate90.conf" --kiosk-frames 2 --screenshot "$out/rotate90.png" \
	2>"$out/rotate90.log" || exit $?

step() { echo "$(cut -d' ' -f1 /proc/uptime) $*" >>"$out/steps.log"; }
# wait_for LOG PATTERN [COUNT [SECONDS]]: until LOG has COUNT lines matching PATTERN
wait_for() {
	i=0
	while [ "$(grep -c "$2" "$1")" -lt "${3:-1}" ] && [ $i -lt $((${4:-20} * 4)) ]; do
		sleep 0.25
		i=$((i + 1))
	done
	[ "$(grep -c "$2" "$1")" -ge "${3:-1}" ] || step "timed out waiting for: $2"
}
shot() { "$scanout" /dev/dri/card0 "$out/$1.png" "${2:-0}" 2>>"$out/steps.log"; step "scanout $1: $?"; }
# a connector's status forced through sysfs sends no uevent on bochs (no poll helper):
# a change event of the card, as the kernel sends on a real plug, goes with it
plug() {
	echo "$1" >"$conn/status" && echo change >/sys/class/drm/card0/uevent
	step "connector $1: $(cat "$conn/status")"
}
# stop PID NAME: SIGTERM, and the kiosk's log and exit status kept
stop() {
	kill -TERM "$1"
	wait "$1"
	echo $? >"$out/$2.rc"
	cp "/tmp/$2.log" "$out/$2.log"
}

# bounded: the first frame takes ~10 s under TCG
"$edaha" --config "$here/rotate90.conf" 2>/tmp/rotate90-idle.log &
pid=$!
wait_for /tmp/rotate90-idle.log "first frame on screen" 1 120
shot rotate90-screen 90
stop $pid rotate90-idle

seatd -g video 2>/tmp/seatd.log &
seatd=$!
i=0
while [ ! -S /run/seatd.sock ] && [ $i -lt 40 ]; do sleep 0.25; i=$((i + 1)); done
step "seatd up, VT $(cat /sys/class/tty/tty0/active)"
"$edaha" 2>/tmp/idle.log &
pid=$!
wait_for /tmp/idle.log "first frame on screen" 1 120
shot idle-first
sleep 3 # time for frames the kiosk should not draw
plug off
wait_for /tmp/idle.log "Virtual-1 disconnected"
sleep 1
plug detect
wait_for /tmp/idle.log "mode set again" 1
shot idle-replugged
# chvt waits until the switch is done: the kiosk must let the VT go
timeout 20 busybox chvt 2
step "chvt 2: $?, VT $(cat /sys/class/tty/tty0/active)"
wait_for /tmp/idle.log "switched away"
shot idle-console
timeout 20 busybox chvt 1
step "chvt 1: $?, VT $(cat /sys/class/tty/tty0/active)"
wait_for /tmp/idle.log "mode set again" 2
shot idle-back
sleep 2 # nothing more should be drawn
stop $pid idle
kill $seatd 2>/dev/null
wait $seatd
cp /tmp/seatd.log "$out/seatd.log"
exit "$(cat "$out/idle.rc")"

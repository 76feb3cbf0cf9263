#!/bin/sh
# The guest half of resize.sh, run inside the VM: resize_guest.sh EDAHA SCANOUT OUT
# edaha as an idle kiosk on the virtio-gpu display (1280x800); after its first frame the
# screen goes to OUT/before.png and OUT/ready tells the host to resize the display. When
# the kiosk has set its new mode, the screen (the 1280x800 picture fitted into the new
# mode) goes to OUT/after.png, sampled back to 1280x800; then SIGTERM.
edaha=$1 scanout=$2 out=$3

# wait_for PATTERN SECONDS: until the kiosk's log has a line matching PATTERN
wait_for() {
	i=0
	while ! grep -q "$1" /tmp/kiosk.log && [ $i -lt $(($2 * 4)) ]; do
		sleep 0.25
		i=$((i + 1))
	done
	grep -q "$1" /tmp/kiosk.log || echo "resize_guest: timed out waiting for: $1" >&2
}

"$edaha" 2>/tmp/kiosk.log &
pid=$!
# bounded: the first frame takes ~10 s under TCG
wait_for "first frame on screen" 120
"$scanout" /dev/dri/card0 "$out/before.png"
touch "$out/ready"
wait_for "mode set again" 90
# the modeset is done when the kiosk says so: the frame is on screen
"$scanout" /dev/dri/card0 "$out/after.png" 0 1280x800
cp /sys/class/drm/card0-Virtual-1/modes "$out/modes"
kill -TERM $pid
wait $pid
rc=$?
cp /tmp/kiosk.log "$out/kiosk.log"
exit $rc

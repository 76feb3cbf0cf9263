#!/bin/sh
# The guest half of display.sh, run inside the VM: display_guest.sh EDAHA FRAMES OUTDIR
#  1. edaha --kiosk-frames FRAMES --screenshot OUTDIR/kiosk.png (a frame every vblank)
#  2. edaha as a kiosk starts, idle: after its first frame it must draw nothing more
#     until SIGTERM, which must end it cleanly (status 0).
edaha=$1 frames=$2 out=$3
"$edaha" --kiosk-frames "$frames" --screenshot "$out/kiosk.png" 2>"$out/kiosk.log" || exit $?

"$edaha" 2>/tmp/idle.log &
pid=$!
i=0
# bounded: the first frame takes ~10 s under TCG
while ! grep -q "first frame on screen" /tmp/idle.log && [ $i -lt 120 ]; do
	sleep 1
	i=$((i + 1))
done
sleep 3 # time for frames the kiosk should not draw
kill -TERM $pid
wait $pid
rc=$?
cp /tmp/idle.log "$out/idle.log"
exit $rc

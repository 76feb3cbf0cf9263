#!/bin/sh
# The guest half of kiosk.sh: edaha as the kiosk on the VM's DRM device, a session drawn
# with the virtual pen (uinput_pen, kiosk.script) and the GPIO buttons (gpio-sim).
# Then the kiosk again in a breeze (kiosk_wind.conf): the session's drawing restored from
# the state directory, left alone (two scanouts a second apart under the attract screen),
# then drawn on while it sways (wind.script).
#   kiosk_guest.sh EDAHA UINPUT_PEN KMOD_DIR SCANOUT
# Writes to /out: kiosk.log, stats.txt, session.edaha-trace, final.png, leds, export/;
# wind.log, wind-stats.txt, sway-a.png, sway-b.png.
edaha=$1 pen=$2 kmod=$3 scanout=$4
H=$(dirname "$0")
modprobe uinput || exit 3
# kiosk.conf's export and state directories are in /tmp, where the host's files show
# through: a journal or export left there by anyone must not be this session's start
rm -rf /tmp/export /tmp/state
"$H/gpio_sim.sh" setup "$kmod" || exit 3
export GPIO="$H/gpio_sim.sh"
"$edaha" --config "$H/kiosk.conf" --record /out/session.edaha-trace --screenshot /out/final.png \
	--stats >/out/stats.txt 2>/out/kiosk.log &
pid=$!
# bounded waits: the first frame takes ~10 s under TCG
wait_for() { # PATTERN SECONDS [LOG]
	i=0
	while ! grep -q "$1" "${3:-/out/kiosk.log}" && [ $i -lt "$2" ]; do
		sleep 1
		i=$((i + 1))
	done
	grep -q "$1" "${3:-/out/kiosk.log}"
}
wait_for "first frame on screen" 150 || echo "kiosk_guest: no first frame" >&2
: >/tmp/leds
export TABLET_ADDED="$H/tablet_added.sh /out/kiosk.log"
UINPUT_PEN_WAIT_MS=0 "$pen" <"$H/kiosk.script" 2>/out/pen.err || echo "kiosk_guest: uinput_pen failed" >&2
wait_for "edaha: export" 60 || echo "kiosk_guest: no export" >&2
sleep 6 # the "saved" message goes (4 s) before the last frame is taken
kill -TERM $pid
wait $pid
rc=$?
cp /tmp/leds /out/leds
mkdir -p /out/export && cp -r /tmp/export/. /out/export/ 2>/dev/null
[ $rc -eq 0 ] || exit $rc

# In a breeze: every frame drawn, at the display's rate up to max_fps
"$edaha" --config "$H/kiosk_wind.conf" --stats >/out/wind-stats.txt 2>/out/wind.log &
pid=$!
wait_for "first frame on screen" 150 /out/wind.log || echo "kiosk_guest: no first frame in the wind" >&2
sleep 10 # grown in (at most 6 s), the attract screen up (4 s)
"$scanout" /dev/dri/card0 /out/sway-a.png || echo "kiosk_guest: no scanout" >&2
sleep 1
"$scanout" /dev/dri/card0 /out/sway-b.png || echo "kiosk_guest: no scanout" >&2
export TABLET_ADDED="$H/tablet_added.sh /out/wind.log"
UINPUT_PEN_WAIT_MS=0 "$pen" <"$H/wind.script" 2>>/out/pen.err || echo "kiosk_guest: uinput_pen failed" >&2
kill -TERM $pid
wait $pid

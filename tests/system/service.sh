#!/bin/bash
# System test of the kiosk as a service: edaha installed by `meson install` onto the VM's
# root (vm.sh -r), systemd as PID 1 (vm.sh -i systemd) creating the edaha user, its state
# directory and the device rules at boot, and edaha.service started as at boot. Checks:
#   - the service reports READY (systemctl start returns, active/running) and runs as
#     the edaha user with the GPIO chip opened through the udev rule's group, no
#     capabilities, NoNewPrivs and a seccomp filter; it draws to the DRM device (the
#     display's scanout is the kiosk's empty canvas, then the drawing);
#   - SIGKILL in the middle of a stroke: systemd restarts it and the drawing comes back
#     as it was, without the stroke in progress (scanouts before and after compared);
#   - a stalled main loop (SIGSTOP): the watchdog notices, systemd restarts it, the
#     drawing comes back again;
#   - nobody draws for kiosk.reset_after: the drawing is archived (it loads back with its
#     strokes) and the canvas is clean.
# Environment from meson: EDAHA, IMGCMP, VM, UINPUT_PEN, SCANOUT, KMOD_DIR, BUILD_ROOT,
# EDAHA_GL_PRELOAD (ASan builds).
set -uo pipefail
: "${EDAHA:?}" "${IMGCMP:?}" "${VM:?}" "${UINPUT_PEN:?}" "${SCANOUT:?}" "${KMOD_DIR:?}" "${BUILD_ROOT:?}"
HERE=$(cd "$(dirname "$0")" && pwd)
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-service.XXXXXX")
trap '[ -n "${KEEP:-}" ] && echo "kept $T" || rm -rf "$T"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

command -v /lib/systemd/systemd >/dev/null || { echo "SKIP: no systemd"; exit 77; }
"$HERE/build_kmods.sh" "$KMOD_DIR"
rc=$?
[ $rc -eq 77 ] && exit 77
[ $rc -eq 0 ] || fail "cannot build the gpio-sim module"
. "$HERE/gl_env.sh"

# the product as installed, plus the test's configuration and shorter watchdog times (the
# guest is slow)
. "$HERE/installed_root.sh"
root=$T/root
installed_root "$root" "$HERE/service.conf" WatchdogSec=12 TimeoutAbortSec=3 RestartSec=1 ||
	fail "meson install into $root failed"

"$VM" -t 900 -s 640x400 -i systemd -r "$root" -o "$T/vm" -- \
	"$HERE/service_guest.sh" "$UINPUT_PEN" "$SCANOUT" "$KMOD_DIR"
rc=$?
[ $rc -eq 77 ] && exit 77
[ $rc -eq 0 ] || fail "the guest exited $rc"
v=$T/vm
log=$v/edaha.log
grep -v '^MESA-LOADER\|^failed to load driver\|^pci id for fd\|^kmsro' "$log" | sed 's/^/  | /' | tail -60

# 1. started, ready, unprivileged, drawing
grep -q 'ActiveState=active' "$v/status-start.txt" && grep -q 'SubState=running' "$v/status-start.txt" ||
	fail "edaha.service not active after start: $(cat "$v/status-start.txt")"
grep -q 'Type=notify' "$v/status-start.txt" || fail "not Type=notify"
grep -q 'WatchdogUSec=12s' "$v/status-start.txt" || fail "no watchdog: $(grep Watchdog "$v/status-start.txt")"
grep -q "first frame on screen" "$log" || fail "no first frame"
echo "  $(cat "$v/ready.txt") (systemctl start, until READY=1)"
read -r user group groups < "$v/proc.txt"
[ "$user" = edaha ] && [ "$group" = edaha ] || fail "runs as $user:$group, not edaha"
for g in video render input gpio; do
	echo ",$groups," | grep -q ",$g," || fail "edaha lacks group $g ($groups)"
done
grep -q '^CapEff:.*0000000000000000' "$v/proc.txt" || fail "has capabilities: $(cat "$v/proc.txt")"
grep -q '^NoNewPrivs:.*1' "$v/proc.txt" || fail "NoNewPrivs not set"
grep -q '^Seccomp:.*2' "$v/proc.txt" || fail "no seccomp filter"
grep -q ' gpio ' "$v/gpiochips.txt" || fail "the gpio chip is not group gpio: $(cat "$v/gpiochips.txt")"
if grep -q '^edaha: warning' "$log"; then
	fail "the kiosk warned: $(grep '^edaha: warning' "$log")"
fi
grep -q 'edaha: input: edaha virtual pen added' "$log" || fail "the pen was not picked up"
grep -qi 'gpio.*kiosk-buttons\|button' "$log" || true

# 2. SIGKILL mid-stroke: back with the two committed strokes
grep -q 'NRestarts=1' "$v/status-kill.txt" || fail "not restarted once after SIGKILL: $(cat "$v/status-kill.txt")"
grep -q 'the drawing is back from /var/lib/edaha/drawing.journal (2 edits, 2 in effect)' "$log" ||
	fail "the drawing did not come back with its 2 strokes after SIGKILL"
for f in before-kill after-kill after-watchdog after-reset; do
	[ -s "$v/$f.png" ] || fail "no scanout $f.png: $(cat "$v/scanout.err")"
done
"$IMGCMP" --max-diff 16 --max-fraction 0.001 "$v/before-kill.png" "$v/after-kill.png" ||
	fail "the screen after SIGKILL is not the screen before"
# the screen shows a drawing: not the empty canvas the reset leaves
"$IMGCMP" --max-diff 16 --max-fraction 0.001 "$v/before-kill.png" "$v/after-reset.png" >/dev/null 2>&1 &&
	fail "the drawing and the empty canvas look the same"

# 3. the watchdog
grep -q 'NRestarts=2' "$v/status-watchdog.txt" || fail "not restarted after the stall: $(cat "$v/status-watchdog.txt")"
grep -qi 'watchdog timeout' "$v/watchdog.txt" || fail "systemd saw no watchdog timeout: $(cat "$v/watchdog.txt")"
echo "  $(grep -i -m1 'watchdog timeout' "$v/watchdog.txt")"
[ "$(grep -c 'the drawing is back from' "$log")" -ge 2 ] || fail "the drawing did not come back after the watchdog"
"$IMGCMP" --max-diff 16 --max-fraction 0.001 "$v/before-kill.png" "$v/after-watchdog.png" ||
	fail "the screen after the watchdog restart is not the screen before"

# 4. the idle reset
grep -q 'the drawing is archived as archive/drawing-000001.edaha; a new canvas' "$log" ||
	fail "no idle reset to the archive"
[ -s "$v/archive/drawing-000001.edaha" ] || fail "no archived drawing"
env "${host_env[@]}" "$EDAHA" --headless --load "$v/archive/drawing-000001.edaha" --out "$T/loaded" \
	>"$T/load.log" 2>&1 || { cat "$T/load.log"; fail "the archived drawing does not load"; }
grep -qx 'history 2 2' "$v/archive/drawing-000001.edaha" ||
	fail "the archived drawing is not the two strokes: $(grep '^history' "$v/archive/drawing-000001.edaha")"
grep -q '"id":1,"parent":0' "$T/loaded/skeleton.json" || fail "the archived drawing has no branch on its trunk"
env "${host_env[@]}" "$EDAHA" --headless --size 640x400 --out "$T/empty" >/dev/null 2>&1 ||
	fail "no headless empty canvas"
"$IMGCMP" --max-diff 64 --max-fraction 0.015 "$T/empty/screen.png" "$v/after-reset.png" ||
	fail "after the reset the screen is not an empty canvas"
# 5. today's forest: the idle reset's drawing planted as No. 1; the second visitor's
# archived and the kiosk killed while planting it: back, both stand, archived once
grep -q 'forest: the drawing is No. 1 in today.s forest' "$log" ||
	fail "the idle reset did not say the drawing's number in today's forest"
grep -q 'forest: No. 1 planted (drawing-000001.edaha)' "$log" || fail "the archived drawing was not planted"
grep -q 'archived as archive/drawing-000002.edaha' "$log" || fail "the second drawing was not archived"
echo "  the second drawing archived, the kiosk SIGKILLed at once: $(cat "$v/kill-planting.txt" 2>/dev/null)"
grep -q 'forest: 2 trees standing (No. 1 to 2)' "$log" || fail "after the SIGKILL, not both trees in the forest"
grep -q 'archived as archive/drawing-000003' "$log" && fail "a drawing was archived twice (the journal's, after the SIGKILL)"
env "${host_env[@]}" "$EDAHA" --headless --out "$T/attract" --idle 120 --size 640x400 \
	>"$T/attract.log" 2>&1 || { cat "$T/attract.log"; fail "no headless attract screen"; }
for f in forest-1 forest-2; do
	[ -s "$v/$f.png" ] || fail "no scanout $f.png"
	"$IMGCMP" --max-diff 32 --max-fraction 0.05 "$T/attract/screen.png" "$v/$f.png" >/dev/null 2>&1 &&
		fail "$f.png: the attract screen shows no forest"
done
"$IMGCMP" --max-diff 16 --max-fraction 0.002 "$v/forest-1.png" "$v/forest-2.png" >/dev/null 2>&1 &&
	fail "the forest of two is the forest of one"
# 6. the clock past the reset hour: a new day at once, the forest empty, the invitation
# as on any day; the day file's first tree the next archive number
grep -q 'drawing-000003.edaha and later are today.s forest' "$log" || fail "no new day at the reset hour"
grep -qx 'first: 3' "$v/forest-day-2" || fail "the new day's file: $(cat "$v/forest-day-2")"
"$IMGCMP" --max-diff 64 --max-fraction 0.015 "$T/attract/screen.png" "$v/forest-day.png" ||
	fail "after the new day the attract screen is not the plain invitation"
echo "  guest timeline:"; sed 's/^/    /' "$v/phases.txt"
echo "system-service: OK"

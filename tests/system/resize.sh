#!/bin/bash
# System test of a display that comes back with another mode: boots a VM (vm.sh) with a
# virtio-gpu at 1280x800 and a VNC server, runs the kiosk idle (resize_guest.sh), and once
# it shows its first frame asks QEMU through VNC to resize the display to 1024x768
# (vnc_resize.py), as a viewer's window resize does. The guest gets a real hotplug
# uevent (HOTPLUG=1) and its connector no longer offers 1280x800. The kiosk must say the
# connector is back at 1024x768, set that mode, keep its 1280x800 picture and show it
# scaled to fit (1024x640, black bars above and below: scanout checks the bars and
# samples the picture back), draw exactly one more frame and end cleanly on SIGTERM.
# Environment from meson: EDAHA, IMGCMP, SCANOUT, VM, EDAHA_GL_PRELOAD (ASan builds).
set -uo pipefail
: "${EDAHA:?}" "${IMGCMP:?}" "${SCANOUT:?}" "${VM:?}"
HERE=$(cd "$(dirname "$0")" && pwd)
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-resize.XXXXXX")
trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

. "$(dirname "$0")/gl_env.sh"
env "${host_env[@]}" "$EDAHA" --headless --out "$T/headless" >"$T/headless.log" 2>&1 ||
	{ cat "$T/headless.log" >&2; fail "headless render exited $?"; }

mkdir -p "$T/vm"
"$VM" -t 300 -g virtio -v "$T/vnc.sock" -o "$T/vm" -- env "${guest_env[@]}" \
	"$HERE/resize_guest.sh" "$EDAHA" "$SCANOUT" /out &
vm=$!
# bounded by the VM's own limit: it ends, or the kiosk is up
while [ ! -e "$T/vm/ready" ] && kill -0 $vm 2>/dev/null; do sleep 0.5; done
resized=no
# on failure the guest gives up waiting for the new mode and ends by itself
[ -e "$T/vm/ready" ] && python3 "$HERE/vnc_resize.py" "$T/vnc.sock" 1024 768 && resized=yes
wait $vm
rc=$?
[ $rc -eq 77 ] && exit 77 # vm.sh said why it skips
grep -v '^MESA-LOADER\|^failed to load driver\|^pci id for fd\|^kmsro' "$T/vm/kiosk.log" 2>/dev/null
[ $resized = yes ] || fail "the VNC client could not resize the display"
[ $rc -eq 0 ] || fail "edaha in the VM exited $rc"

has() { grep -q -- "$1" "$T/vm/kiosk.log" || fail "the log does not say \"$1\""; }
has "kiosk on /dev/dri/card0 Virtual-1 1280x800@[0-9]* (atomic, direct)"
has "Virtual-1 connected, 1024x768@"
has "mode set again on Virtual-1"
has "^edaha: 2 frames;"
grep -q "^1280x800$" "$T/vm/modes" && fail "the resized display still offers 1280x800: nothing tested"
"$IMGCMP" --max-diff 64 --max-fraction 0.005 --diff "$T/diff-before.png" \
	"$T/headless/screen.png" "$T/vm/before.png" || fail "the first frame is not the headless render"
# scaled to 0.8 with linear filtering and sampled back: edges soften (about 400 pixels
# differ); the empty kiosk is mostly flat, so a picture 2 pixels off already makes 2000
"$IMGCMP" --max-diff 96 --max-fraction 0.001 --diff "$T/diff-after.png" \
	"$T/headless/screen.png" "$T/vm/after.png" ||
	fail "the resized screen does not show the 1280x800 picture fitted into 1024x768"
echo "system-display-resize: OK"

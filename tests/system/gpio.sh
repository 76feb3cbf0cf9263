#!/bin/bash
# System test of the GPIO buttons: boots a VM (vm.sh), makes a gpio-sim chip
# "kiosk-buttons" (gpio_sim.sh; the module built by build_kmods.sh into KMOD, as
# Debian's kernel lacks gpio-sim) and runs input_probe with gpio.conf:
# buttons found by chip label and line name or offset, active-low with pull-up, pressed
# and released through gpio-sim's pulls, a release within the debounce time read when it
# closes, a bounce dropped; the active mode's LED lit; a missing chip and a
# missing line are warnings, not failures.
# Environment: VM, INPUT_PROBE (tests/platform/input_probe), KMOD.
set -uo pipefail
: "${VM:?}" "${INPUT_PROBE:?}" "${KMOD:?}"
HERE=$(cd "$(dirname "$0")" && pwd)
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-gpio.XXXXXX")
trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
"$HERE/build_kmods.sh" "$KMOD"
rc=$?
[ $rc -eq 77 ] && exit 77
[ $rc -eq 0 ] || fail "cannot build the gpio-sim module"

"$VM" -t 150 -g none -o "$T/vm" -- sh -c '"$0" "$1" "$2"' "$HERE/gpio_guest.sh" "$INPUT_PROBE" "$KMOD"
rc=$?
[ $rc -eq 77 ] && exit 77
cat "$T/vm/probe.err" 2>/dev/null
[ $rc -eq 0 ] || fail "the VM job exited $rc"
grep -q 'input_probe: [0-9]* events' "$T/vm/probe.err" || fail "input_probe did not end cleanly"
tr=$T/vm/probe.trace
grep -q 'input_probe: 4 GPIO buttons, 2 LEDs' "$T/vm/probe.err" || fail "not 4 buttons and 2 LEDs"
grep -q 'button undo (chip "no-such-chip".*no such chip' "$T/vm/probe.err" || fail "no warning for the missing chip"
grep -q 'button new .*no such line' "$T/vm/probe.err" || fail "no warning for the missing line"
for b in 3d clone export; do
	[ "$(grep -c " button $b pressed$" "$tr")" -eq 1 ] || fail "$b: expected one press"
	[ "$(grep -c " button $b released$" "$tr")" -eq 1 ] || fail "$b: expected one release"
done
# leaf bounced (press, release, press within the window) and stays pressed
[ "$(grep -c ' button leaf pressed$' "$tr")" -eq 1 ] || fail "leaf: expected one press"
grep -q ' button leaf released$' "$tr" && fail "leaf: a bounce came through as a release"
grep -qx 'after-3d 1 0' "$T/vm/leds" || fail "3d's LED is not the one lit after 3d: $(head -1 "$T/vm/leds")"
grep -qx 'after-clone 0 1' "$T/vm/leds" || fail "clone's LED is not the one lit after clone"
echo "system-gpio: OK"

#!/bin/bash
# System test of the pen input: boots a VM (vm.sh),
# makes a virtual pen tablet with uinput (uinput_pen, driven by pen.script) and records
# what platform/input/input_libinput.c makes of it through libinput's udev backend
# (input_probe, an edaha trace). Checks the pen and eraser strokes, the stylus button,
# the positions (the tablet's 16:10 onto the 1280x800 screen) and that the tablet
# unplugged and plugged back mid-session is picked up again; then replays the trace with
# `edaha --headless`. A touchscreen's finger then draws like the pen.
# Environment: EDAHA, VM, UINPUT_PEN, INPUT_PROBE (from the build: tests/platform/).
# The plain build runs it, ASan builds do not: tests/system/meson.build says why.
set -uo pipefail
: "${EDAHA:?}" "${VM:?}" "${UINPUT_PEN:?}" "${INPUT_PROBE:?}"
HERE=$(cd "$(dirname "$0")" && pwd)
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-pen.XXXXXX")
trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
. "$HERE/gl_env.sh"

# udev is slow under TCG: the script waits until input_probe has the tablet (tablet_added.sh).
# input_probe stops on SIGTERM once the script is done (its --seconds is only a bound).
# Then a touchscreen (touch.script): its first finger draws like the pen.
"$VM" -t 240 -g none -o "$T/vm" -- sh -c 'modprobe uinput || exit 3; "$0" --config /nonexistent --seconds 200 >/out/probe.trace 2>/out/probe.err & p=$!; sleep 1.5; export TABLET_ADDED="$3 /out/probe.err" UINPUT_PEN_WAIT_MS=0; "$1" <"$2" 2>/out/pen.err; "$1" --touch <"$4" 2>>/out/pen.err; sleep 1; kill -TERM $p; wait $p' \
	"$INPUT_PROBE" "$UINPUT_PEN" "$HERE/pen.script" "$HERE/tablet_added.sh" "$HERE/touch.script"
rc=$?
[ $rc -eq 77 ] && exit 77
cat "$T/vm/pen.err" "$T/vm/probe.err" 2>/dev/null | grep -v '^event[0-9]* *-\|^libinput info'
[ $rc -eq 0 ] || fail "the VM job exited $rc"
tr=$T/vm/probe.trace
count() { grep -c -- "$1" "$tr"; }
[ "$(grep -c 'virtual pen added' "$T/vm/probe.err")" -eq 2 ] || fail "the tablet was not added twice (hotplug)"
# the pen's stroke, then the finger's
# libinput forces a tool out of proximity after ~50 ms without events (a slow guest), and
# it comes back in: at least one proximity-in each, not exactly
[ "$(count ' proximity-in pen ')" -ge 2 ] || fail "expected pen proximity-ins (pen, finger)"
[ "$(count ' tip-down pen ')" -eq 2 ] || fail "expected two pen tip-downs (pen, finger)"
grep -q 'edaha virtual touchscreen added (touch' "$T/vm/probe.err" || fail "the touchscreen was not added as one"
[ "$(count ' motion pen ')" -ge 5 ] || fail "expected pen motion"
[ "$(count ' pen-button stylus pressed ')" -eq 1 ] || fail "expected the stylus button"
[ "$(count ' proximity-in eraser ')" -ge 1 ] || fail "expected the eraser after the replug"
[ "$(count ' tip-down eraser ')" -eq 1 ] || fail "expected an eraser tip-down"
# the pen's tip came down at the tablet's centre: the screen's centre
awk '$2 == "tip-down" && $3 == "pen" { if (++n == 1 && ($4 < 635 || $4 > 645 || $5 < 395 || $5 > 405)) exit 1 }' "$tr" ||
	fail "the tip-down is not at the screen's centre"
# the finger came down a quarter across the touchscreen and drew to its middle
awk '$2 == "tip-down" && $3 == "pen" { if (++n == 2 && ($4 < 315 || $4 > 325 || $5 < 395 || $5 > 405)) exit 1 }' "$tr" ||
	fail "the finger's tip-down is not a quarter across the screen"
tail -5 "$tr" | awk '$2 == "motion" { x = $4 } END { exit !(x > 630 && x < 650) }' ||
	fail "the finger's stroke did not reach the middle"
env "${host_env[@]}" "$EDAHA" --headless --replay "$tr" --out "$T/out" >"$T/replay.log" 2>&1 ||
	{ cat "$T/replay.log" >&2; fail "edaha --headless does not replay the recorded trace"; }
echo "system-pen: OK ($(grep -c . "$tr") lines of trace)"

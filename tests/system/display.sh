#!/bin/bash
# System test of the kiosk display: boots a VM (vm.sh) with a bochs-display, runs
# `edaha --kiosk-frames 30 --screenshot` on its real DRM device (modeset, GBM, EGL, page
# flips) and checks on the host that the last frame shows the kiosk: the same picture as a
# headless render of the same empty drawing, within imgcmp's tolerance. Prints the frame
# rate and the time to the first frame (from an emulated CPU and llvmpipe: slow). Then
# starts the kiosk plainly and checks that, with nothing happening, it draws its first
# frame only and ends cleanly on SIGTERM.
# Environment from meson: EDAHA, IMGCMP, VM, EDAHA_GL_PRELOAD (ASan builds).
set -uo pipefail
: "${EDAHA:?}" "${IMGCMP:?}" "${VM:?}"
FRAMES=30
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-system.XXXXXX")
trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# Under ASan the GL driver is preloaded into edaha only (see tests/meson.build); the
# guest gets the same environment, as it runs the host's files.
guest_env=(LP_NATIVE_VECTOR_WIDTH=128)
host_env=()
if [ -n "${EDAHA_GL_PRELOAD:-}" ]; then
	host_env=(LD_PRELOAD="$EDAHA_GL_PRELOAD" ASAN_OPTIONS="${ASAN_OPTIONS:-}:verify_asan_link_order=0")
	guest_env+=("${host_env[@]}" UBSAN_OPTIONS="${UBSAN_OPTIONS:-}" LSAN_OPTIONS="${LSAN_OPTIONS:-}")
fi

env "${host_env[@]}" "$EDAHA" --headless --out "$T/headless" >"$T/headless.log" 2>&1 ||
	{ cat "$T/headless.log" >&2; fail "headless render exited $?"; }

# llvmpipe's 256-bit vectors are slow under TCG; 128-bit ones halve the frame time there
"$VM" -t 300 -o "$T/vm" -- env "${guest_env[@]}" \
	"$(dirname "$0")/display_guest.sh" "$EDAHA" "$FRAMES" /out
rc=$?
[ $rc -eq 77 ] && exit 77 # vm.sh said why it skips
for log in kiosk idle; do
	grep -v '^MESA-LOADER\|^failed to load driver\|^pci id for fd\|^kmsro' "$T/vm/$log.log" 2>/dev/null
done
[ $rc -eq 0 ] || fail "edaha in the VM exited $rc"
grep -q "^edaha: $FRAMES frames" "$T/vm/kiosk.log" || fail "the log does not say $FRAMES frames were shown"
# idle: one frame (the first), then nothing until SIGTERM ended it cleanly
grep -q "^edaha: Terminated, stopping" "$T/vm/idle.log" || fail "the idle kiosk did not stop on SIGTERM"
grep -q "^edaha: 1 frame;" "$T/vm/idle.log" || fail "the idle kiosk drew more than its first frame"
# Multisampled edges are resolved by a different path than the headless framebuffer's:
# a few hundred edge pixels differ; a missing or misplaced button or colour would not fit.
"$IMGCMP" --max-diff 64 --max-fraction 0.005 --diff "$T/diff.png" \
	"$T/headless/screen.png" "$T/vm/kiosk.png" || fail "the kiosk's frame is not the headless render"
echo "system-display: OK"

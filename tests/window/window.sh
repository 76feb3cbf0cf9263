#!/bin/bash
# The window on a desktop (issue 18), under Xvfb: xdotool draws the demo drawing's strokes
# with the pointer into `edaha --window` made smaller than its picture (the app keeps its
# size, the picture is scaled, the pointer mapped back), presses the 3D button with the
# key 1 and grow with the key 7 (its worker's result must be taken while frames go on),
# and stops it with SIGTERM. Then: the recording has the strokes where the demo
# has them and the key's press; the window's screenshot matches the headless replay of its
# own recording as the system tests' kiosk does; and the window's frame figures (--stats)
# are printed. Skips (77) only without Xvfb or xdotool, or in a build without the window.
# Paths come from meson: EDAHA, IMGCMP, SRC (the source tree's tests/ folder).
set -uo pipefail
: "${EDAHA:?}" "${IMGCMP:?}" "${SRC:?}"
. "$SRC/tools/edaha.sh"
. "$SRC/tools/xvfb.sh"
for p in Xvfb xdotool python3; do
	command -v $p >/dev/null || { echo "SKIP: no $p (tools/deps.sh TEST_PKGS has it)"; exit 77; }
done
"$EDAHA" --version | grep -q "^window: yes" ||
	{ echo "SKIP: this build has no window (no libsdl2-dev)"; exit 77; }
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-window.XXXXXX")
XVFB='' APP=''
cleanup() {
	[ -n "$APP" ] && kill "$APP" 2>/dev/null
	[ -n "$XVFB" ] && kill "$XVFB" 2>/dev/null
	wait 2>/dev/null
	rm -rf "$T"
}
trap cleanup EXIT

xvfb_start "$T" 1600x1000 || fail "Xvfb did not start"
DISPLAY=$XVFB_DISPLAY
export DISPLAY
unset WAYLAND_DISPLAY
export SDL_VIDEODRIVER=x11

cat >"$T/edaha.conf" <<CONF
kiosk:
  attract_after: 0
  # still: the screenshot is compared with a headless replay, which has no wind
  wind: 0
  export_dir: none
  state_dir: $T/state
  reset_after: 0
usb:
  enabled: false
CONF
mkdir "$T/state"
# DISPLAY is set: a window without --window, as tools/run starts it. Not the edaha
# function: its subshell would get the SIGTERM, not edaha
preload=()
[ -n "${EDAHA_GL_PRELOAD:-}" ] && preload=(env "LD_PRELOAD=$EDAHA_GL_PRELOAD"
	"ASAN_OPTIONS=${ASAN_OPTIONS:-}:verify_asan_link_order=0")
"${preload[@]}" "$EDAHA" --config "$T/edaha.conf" --seed 7 --record "$T/window.edaha-trace" \
	--screenshot "$T/window.png" --stats >"$T/stats" 2>"$T/stderr" &
APP=$!
for _ in $(seq 300); do
	grep -q "first frame on screen" "$T/stderr" && break
	kill -0 $APP 2>/dev/null || break
	sleep 0.1
done
grep -q "first frame on screen" "$T/stderr" || { cat "$T/stderr" >&2; fail "no first frame"; }
grep -q "^edaha: window on an SDL x11 window" "$T/stderr" ||
	{ cat "$T/stderr" >&2; fail "not a window"; }
WID=$(xdotool search --sync --name '^edaha$' | head -n 1)
[ -n "$WID" ] || fail "no window named edaha"

# three quarters of the picture's size: 1280x800 shown at 960x600
xdotool windowsize --sync "$WID" 960 600 || fail "xdotool cannot resize the window"
sleep 0.5
python3 "$SRC/window/trace2xdo.py" "$SRC/data/demo.edaha-trace" "$WID" 0.75 >"$T/draw.xdo" ||
	fail "trace2xdo"
xdotool "$T/draw.xdo" || fail "xdotool could not draw"
# the pointer stays over the window: the key goes to it
xdotool key 1 || fail "xdotool could not press a key"
# the turn into 3D takes 2.4 s; the screenshot is the screen when the kiosk stops
sleep 4
# grow (key 7) runs on its worker while the window keeps drawing (a window's swap is done
# at once, unlike a DRM flip: the loop must still read the worker's result and signals)
xdotool key 7 || fail "xdotool could not press a key"
for _ in $(seq 600); do
	grep -q "^edaha: grew a year" "$T/stderr" && break
	sleep 0.1
done
grep -q "^edaha: grew a year" "$T/stderr" ||
	{ cat "$T/stderr" >&2; fail "the window never took the grow press's result"; }
kill -TERM $APP
for _ in $(seq 100); do kill -0 $APP 2>/dev/null || break; sleep 0.1; done
kill -0 $APP 2>/dev/null && { kill -KILL $APP; fail "edaha did not stop within 10 s of SIGTERM"; }
wait $APP
rc=$?
APP=
[ $rc -eq 0 ] || { cat "$T/stderr" >&2; fail "edaha exited $rc after SIGTERM"; }
grep "^edaha: grew a year" "$T/stderr"

rec=$T/window.edaha-trace
grep -q "^screen 1280 800" "$rec" || fail "the recording's screen is not the picture's 1280x800"
n=$(grep -c " tip-down " "$rec")
[ "$n" -eq "$(grep -c " tip-down " "$SRC/data/demo.edaha-trace")" ] ||
	fail "$n strokes recorded, not the demo's"
grep -q " button 3d pressed" "$rec" || fail "the key 1 did not press the 3D button"
grep -q " button 3d released" "$rec" || fail "the key 1's release is not recorded"
grep -q " button grow pressed" "$rec" || fail "the key 7 did not press the grow button"
# the first stroke starts where the demo's does: the scaled pointer mapped back
read -r x y < <(awk '$2 == "tip-down" { print $4, $5; exit }' "$rec")
awk -v x="$x" -v y="$y" 'BEGIN { exit !((x - 640)^2 + (y - 736)^2 <= 4) }' ||
	fail "the first stroke starts at $x,$y, not at the demo's 640,736"

edaha --headless --out "$T/headless" --seed 7 --replay "$rec" >/dev/null 2>"$T/headless.err" ||
	{ cat "$T/headless.err" >&2; fail "the headless replay failed"; }
"$IMGCMP" --max-diff 64 --max-fraction 0.005 --diff "$T/diff.png" \
	"$T/window.png" "$T/headless/screen.png" ||
	fail "the window's screen differs from the headless replay of its recording"
# and the window showed the 3D tree, not the sketch: the replay without the keys differs
grep -v -e " button 3d " -e " button grow " "$rec" >"$T/no-key.edaha-trace"
edaha --headless --out "$T/no-key" --seed 7 --replay "$T/no-key.edaha-trace" >/dev/null 2>&1 ||
	fail "the headless replay without the key failed"
! "$IMGCMP" --max-diff 64 --max-fraction 0.005 "$T/window.png" "$T/no-key/screen.png" \
	>/dev/null 2>&1 || fail "the window shows the same without the 3D button"

# the window's figures, to quote beside the headless ones
grep "frames; first on screen" "$T/stats" || fail "--stats printed no frame figures"
grep "pen events to screen" "$T/stats" || fail "--stats printed no pen figures"

# Started again, the drawing comes back from the journal; New (key n) archives it as it
# stood, for today's forest (issue 27): the archived drawing loads to the grown tree
"${preload[@]}" "$EDAHA" --config "$T/edaha.conf" >/dev/null 2>"$T/stderr2" &
APP=$!
for _ in $(seq 300); do
	grep -q "first frame on screen" "$T/stderr2" && break
	kill -0 $APP 2>/dev/null || break
	sleep 0.1
done
grep -q "the drawing is back from" "$T/stderr2" || { cat "$T/stderr2" >&2; fail "no drawing back"; }
WID=$(xdotool search --sync --name '^edaha$' | head -n 1)
xdotool mousemove --window "$WID" 100 100 key n || fail "xdotool could not press n"
for _ in $(seq 100); do
	grep -q "^edaha: New: the drawing is archived as archive/drawing-000001.edaha" \
		"$T/stderr2" && break
	sleep 0.1
done
kill -TERM $APP
wait $APP
APP=
grep -q "^edaha: New: the drawing is archived as archive/drawing-000001.edaha" "$T/stderr2" ||
	{ cat "$T/stderr2" >&2; fail "New did not archive the drawing"; }
edaha --headless --out "$T/archived" --load "$T/state/archive/drawing-000001.edaha" \
	>/dev/null 2>&1 || fail "the archived drawing does not load"
grep -q '"wood": *{' "$T/archived/skeleton.json" ||
	fail "the archived drawing is not the grown tree as it stood"
echo "PASS"

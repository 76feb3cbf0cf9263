#!/bin/bash
# page_kiosk.sh: the kiosk's Save writes tree-NNNN.html (issue 28, docs/page.md). The kiosk
# in a window under Xvfb, USB off, kiosk.export_dir the only place a Save goes, started on
# the demo in 3D (--load): Save (the key e) twice gives tree-0001.* and tree-0002.*, each
# with its page, which names its own number and today's date by the local clock (the
# viewer's scripts read once, at start). Started again with EDAHA_THREE_DIR pointing
# nowhere: two Saves write their sets without pages, the kiosk goes on, and its journal
# says so once. Paths from meson: EDAHA, DEMO, EDAHA_GL_PRELOAD. Skips (77) without Xvfb,
# xdotool, a build with the window, or libjs-three.
set -uo pipefail
: "${EDAHA:?}" "${DEMO:?}"
. "$(dirname "$0")/../tools/edaha.sh"
. "$(dirname "$0")/../tools/xvfb.sh"
for p in Xvfb xdotool; do
	command -v $p >/dev/null || { echo "SKIP: no $p (tools/deps.sh TEST_PKGS has it)"; exit 77; }
done
"$EDAHA" --version | grep -q "^window: yes" ||
	{ echo "SKIP: this build has no window (no libsdl2-dev)"; exit 77; }
[ -r /usr/share/javascript/three/three.min.js ] ||
	{ echo "SKIP: libjs-three not installed (Debian: apt-get install libjs-three)"; exit 77; }
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-page-kiosk.XXXXXX")
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

edaha --headless --out "$T/demo" --replay "$DEMO" --press 3d >/dev/null 2>&1 ||
	fail "the demo's drawing"
preload=()
[ -n "${EDAHA_GL_PRELOAD:-}" ] && preload=(env "LD_PRELOAD=$EDAHA_GL_PRELOAD"
	"ASAN_OPTIONS=${ASAN_OPTIONS:-}:verify_asan_link_order=0")

# kiosk NAME [ENV...]: starts the kiosk on the demo, saves twice, stops it; its stderr in
# $T/NAME.err, its sets in $T/NAME/
kiosk() {
	local name=$1 wid
	shift
	mkdir -p "$T/$name-state"
	cat >"$T/$name.conf" <<CONF
kiosk:
  attract_after: 0
  export_dir: $T/$name
  state_dir: $T/$name-state
  reset_after: 0
usb:
  enabled: false
CONF
	env "$@" "${preload[@]}" "$EDAHA" --config "$T/$name.conf" --load "$T/demo/drawing.edaha" \
		>/dev/null 2>"$T/$name.err" &
	APP=$!
	for _ in $(seq 300); do
		grep -q "first frame on screen" "$T/$name.err" && break
		kill -0 $APP 2>/dev/null || break
		sleep 0.1
	done
	grep -q "first frame on screen" "$T/$name.err" || { cat "$T/$name.err" >&2; fail "$name: no first frame"; }
	wid=$(xdotool search --sync --name '^edaha$' | head -n 1)
	[ -n "$wid" ] || fail "$name: no window"
	for n in 1 2; do
		xdotool mousemove --window "$wid" 100 100 key e || fail "xdotool could not press e"
		for _ in $(seq 300); do
			[ "$(grep -c "^edaha: exported " "$T/$name.err")" -ge $n ] && break
			sleep 0.1
		done
	done
	kill -TERM $APP
	wait $APP
	local rc=$?
	APP=
	[ $rc -eq 0 ] || { cat "$T/$name.err" >&2; fail "$name: edaha exited $rc after SIGTERM"; }
}

kiosk with
today=$(LC_ALL=C date +"%-d %B %Y")
for n in 1 2; do
	for ext in glb obj mtl png edaha html; do
		[ -s "$T/with/tree-000$n.$ext" ] || { ls "$T/with" >&2; fail "no tree-000$n.$ext"; }
	done
	grep -q "\"number\":$n,\"date\":\"$today\"" "$T/with/tree-000$n.html" ||
		fail "tree-000$n.html does not say No. $n of $today"
done
[ -z "$(find "$T/with" -name '.*')" ] || fail "temporaries left: $(ls -a "$T/with")"
grep -q "saves carry no page" "$T/with.err" && fail "the page's scripts were there"

kiosk without EDAHA_THREE_DIR="$T/nowhere"
for n in 1 2; do
	[ -s "$T/without/tree-000$n.glb" ] && [ -s "$T/without/tree-000$n.edaha" ] ||
		{ ls "$T/without" >&2; fail "without the scripts: no set $n"; }
	[ ! -e "$T/without/tree-000$n.html" ] || fail "without the scripts: a page"
done
[ "$(grep -c "saves carry no page (tree-NNNN.html): $T/nowhere/three.min.js" "$T/without.err")" = 1 ] ||
	{ cat "$T/without.err" >&2; fail "not said once"; }
echo "the kiosk's Saves: tree-0001.html and tree-0002.html ($(stat -c %s "$T/with/tree-0001.html") bytes) of $today;"
echo "without libjs-three: two sets without pages, said once: $(grep "saves carry no page" "$T/without.err")"

#!/bin/bash
# SPDX-License-Identifier: MIT
# page.sh: the take-home page (issue 28, docs/page.md) in Debian's headless Chromium and,
# when installed, headless Firefox ESR (a second engine: Gecko beside Blink).
# `edaha --headless --out DIR` writes model.html for the demo in 3D and for cherry (and
# the demo in Japanese); page_write makes a Save's tree-0012.html of the demo with a
# hostile date. Each page is opened from a file:// URL with every request but the page's
# own sent to a closed port, and driven through the DevTools protocol (page_cdp.py) or
# Firefox's WebDriver BiDi (page_firefox.py; under Xvfb, which Firefox's WebGL needs):
#  - it draws its first frame, with no console error, no exception, no refusal by its
#    Content-Security-Policy and no request at all;
#  - its elements are the template's, whatever the text: the hostile date is shown as
#    text (textContent), none of it became an element;
#  - the tree at rest (the page's test hook edahaStill) against the kiosk's front view
#    (its screen.png): the masks of tree pixels, each cut to its bounding box, on a grid
#    of 48 cells across (page_masks): IoU at least SIL_IOU, at least SIL_NEAR of each
#    mask's cells within a cell of the other's, the boxes' width/height within SIL_ASPECT;
#    with the wind playing, NEAR_WIND of the cells within a cell; the tree's mean colour
#    within COLOR_MAX of the kiosk's, a channel (the page shows the screen's colours).
#    The page's camera is
#    orthographic, as the kiosk's, so the front views compare as they are;
#  - two screenshots a second apart differ in the crown (the upper half of the tree's
#    box: at least CROWN_MIN of its tree pixels' worth) and not at the trunk's foot: in
#    its lowest 12 rows the outline's edges moved by at most FOOT_EDGE_MAX pixel (a
#    slanted edge's pixel flipping: a sub-pixel move), FOOT_EDGE_MEAN on average;
#  - a 300-pixel drag (mouse events through the protocol) turns the tree by at least
#    TURN_MIN radians, and it stays in the window; a finger's drag back (touch) turns it
#    the other way, as far.
# The drawing's odd text: a drawing full of comments of markup loads to the same page,
# byte for byte, as without them. Without the viewer's scripts (EDAHA_THREE_DIR pointing
# nowhere) the run writes everything else and says why.
# Paths from meson's environment: EDAHA, DEMO, PAGE_CDP, PAGE_FIREFOX, PAGE_MASKS, PAGE_WRITE,
# EDAHA_GL_PRELOAD (ASan builds). Exit 77 (skipped) without chromium or libjs-three.
set -uo pipefail
: "${EDAHA:?}" "${DEMO:?}" "${PAGE_CDP:?}" "${PAGE_FIREFOX:?}" "${PAGE_MASKS:?}" "${PAGE_WRITE:?}"
THREE=/usr/share/javascript/three
CHROMIUM=$(command -v chromium || command -v chromium-browser) ||
	{ echo "chromium not installed, skipping (Debian: apt-get install chromium)" >&2; exit 77; }
[ -r "$THREE/three.min.js" ] && [ -r "$THREE/examples/js/loaders/GLTFLoader.js" ] &&
	[ -r "$THREE/examples/js/controls/OrbitControls.js" ] ||
	{ echo "libjs-three not installed, skipping (Debian: apt-get install libjs-three)" >&2; exit 77; }
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-page.XXXXXX")
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/../tools/edaha.sh"
. "$(dirname "$0")/../tools/xvfb.sh"
run() {
	edaha --headless "$@" >"$T/log" 2>&1 || { cat "$T/log" >&2; fail "edaha $* exited $?"; }
}
# the kiosk's canvas at 1280x800 without the bar (from x 1044, its shadow from 1030),
# the side strip (to x 280) and the ground (from y 732)
KIOSK_BOX="290 0 1020 731"
export SIL_IOU=0.75 SIL_NEAR=0.98 SIL_ASPECT=0.05 NEAR_WIND=0.95 CROWN_MIN=0.02 \
	FOOT_EDGE_MAX=1 FOOT_EDGE_MEAN=0.25 TURN_MIN=0.5 COLOR_MAX=8

run --out "$T/demo" --replay "$DEMO" --press 3d
grep -q "model.html" "$T/log" || fail "the run does not say it wrote model.html"
run --out "$T/cherry" --press tpl-cherry
run --out "$T/demo-ja" --replay "$DEMO" --press 3d --lang ja
"$PAGE_WRITE" "$T/demo/model.glb" "$T/tree-0012.html" 12 en \
	'<img src=x onerror="document.title=1"></script><script>alert(1)</script><!--' ||
	fail "page_write"

# the drawing's odd text (comments: all a drawing holds that is nobody's number) changes
# nothing: the same page, byte for byte
cp "$T/demo/drawing.edaha" "$T/plain.edaha"
{ cat "$T/plain.edaha"; printf '%s\n' '# </script><script>alert(1)</script><!--' \
	'# <img src=x onerror=alert(1)> &amp; "quotes" \u003c'; } >"$T/odd.edaha"
run --load "$T/plain.edaha" --out "$T/plain"
run --load "$T/odd.edaha" --out "$T/odd"
cmp -s "$T/plain/model.html" "$T/odd/model.html" ||
	fail "a drawing's comments changed its page"

# no viewer's scripts: the rest written, and why said
EDAHA_THREE_DIR="$T/nowhere" edaha --headless --out "$T/none" --press tpl-cherry \
	>"$T/none.log" 2>&1 || { cat "$T/none.log" >&2; fail "without libjs-three: exit $?"; }
[ ! -e "$T/none/model.html" ] && [ -s "$T/none/model.glb" ] && [ -s "$T/none/drawing.edaha" ] ||
	fail "without libjs-three: not the files expected: $(ls "$T/none")"
grep -q "no model.html:.*three.min.js" "$T/none.log" || { cat "$T/none.log" >&2; fail "not said why"; }

# Firefox (Gecko) beside Chromium (Blink): its WebGL needs a display even headless (Xvfb)
BROWSERS=chromium
FIREFOX=$(command -v firefox-esr || command -v firefox) && command -v Xvfb >/dev/null &&
	BROWSERS="chromium firefox" ||
	echo "firefox-esr or Xvfb not installed: the page in Chromium only (Debian: apt-get install firefox-esr xvfb)" >&2
case $BROWSERS in
*firefox*)
	trap 'kill $XVFB 2>/dev/null; wait 2>/dev/null; rm -rf "$T"' EXIT
	xvfb_start "$T" 1280x800 || fail "Xvfb did not start"
	;;
esac

for b in $BROWSERS; do
# in Firefox the pages that differ most: cherry (spring's leaf colours, the largest) and
# a Save's page with its hostile date (the demo's model)
pages="demo cherry demo-ja tree-0012"
[ "$b" = firefox ] && pages="cherry tree-0012"
for d in $pages; do
	r=$b-$d
	case $d in
	tree-0012) page=$T/tree-0012.html kiosk=$T/demo/screen.png ;;
	*) page=$T/$d/model.html kiosk=$T/$d/screen.png ;;
	esac
	case $b in
	chromium)
		timeout 300 python3 "$PAGE_CDP" "$CHROMIUM" "$page" "$T/$r-shots" >"$T/$r.json" 2>"$T/$r.err" ||
			{ tail -20 "$T/$r.err" "$T/$r-shots/profile/chromium.log" >&2; fail "chromium: $d"; } ;;
	firefox)
		DISPLAY=$XVFB_DISPLAY timeout 300 python3 "$PAGE_FIREFOX" "$FIREFOX" "$page" \
			"$T/$r-shots" >"$T/$r.json" 2>"$T/$r.err" ||
			{ tail -20 "$T/$r.err" "$T/$r-shots/firefox.log" >&2; fail "firefox: $d"; } ;;
	esac
	for shot in still front later turned; do
		"$PAGE_MASKS" silhouette "$kiosk" $KIOSK_BOX "$T/$r-shots/$shot.png" \
			>"$T/$r-$shot.sil" || fail "$r: no tree in $shot.png"
	done
	"$PAGE_MASKS" wind "$T/$r-shots/front.png" "$T/$r-shots/later.png" >"$T/$r.wind" ||
		fail "$r: the wind's shots"
	"$PAGE_MASKS" turned "$T/$r-shots/later.png" "$T/$r-shots/turned.png" >"$T/$r.turned" ||
		fail "$r: the turned shot"
	python3 - "$T" "$d" "$r" <<'PY' || fail "the page: $r"
import json, os, sys
T, d, r = sys.argv[1:4]
E = {k: float(os.environ[k]) for k in ("SIL_IOU", "SIL_NEAR", "SIL_ASPECT", "NEAR_WIND",
                                       "CROWN_MIN", "FOOT_EDGE_MAX", "FOOT_EDGE_MEAN",
                                       "TURN_MIN", "COLOR_MAX")}
load = lambda name: json.load(open(os.path.join(T, name)))
o = load(r + ".json")
assert o["state"] == "ready", "the page is %s" % o["state"]
assert not o["errors"], "console errors: %s" % o["errors"]
assert not o["requests"], "requests: %s" % o["requests"]
# the template's elements, the canvas the viewer made, nothing else
assert o["elements"] == ("HTML HEAD META META META META TITLE STYLE BODY CANVAS DIV DIV DIV DIV "
                         "DIV SCRIPT SCRIPT SCRIPT SCRIPT SCRIPT SCRIPT"), o["elements"]
texts = o["texts"]
if d == "tree-0012":
    assert o["title"] == "My tree, No. 12", o["title"]
    assert texts[:2] == ["Tree No. 12", '<img src=x onerror="document.title=1"></script>'
                         '<script>alert(1)</script><!--'], texts
elif d == "demo-ja":
    assert o["lang"] == "ja" and o["title"] == "わたしの 木", (o["lang"], o["title"])
    assert texts == [None, None, "ゆびや マウスで うごかすと 木が まわるよ", None], texts
else:
    assert o["lang"] == "en" and o["title"] == "My tree", (o["lang"], o["title"])
    assert texts == [None, None, "Drag to turn the tree. Scroll or pinch to come closer.", None], texts
sil = {s: load("%s-%s.sil" % (r, s)) for s in ("still", "front", "later", "turned")}
st = sil["still"]
aspect = abs(st["page_aspect"] / st["kiosk_aspect"] - 1)
assert st["iou"] >= E["SIL_IOU"], "at rest: IoU %.3f < %.2f" % (st["iou"], E["SIL_IOU"])
assert st["near"] >= E["SIL_NEAR"], "at rest: %.3f of the cells near" % st["near"]
assert aspect <= E["SIL_ASPECT"], "at rest: the boxes' shapes differ by %.3f" % aspect
# the screen's colours (the model's mapped as the kiosk maps them): the tree's mean colour
color = max(abs(a - b) for a, b in zip(st["kiosk_mean"], st["page_mean"]))
assert color <= E["COLOR_MAX"], "at rest: the tree's mean colour %s, the kiosk's %s" % (
    st["page_mean"], st["kiosk_mean"])
for s in ("front", "later"):
    assert sil[s]["near"] >= E["NEAR_WIND"], "%s: %.3f of the cells near" % (s, sil[s]["near"])
w = load(r + ".wind")
assert o["seconds"] >= 0.9 and o["wind_time"][1] - o["wind_time"][0] >= 0.5, (o["seconds"], o["wind_time"])
assert w["crown_differ"] >= E["CROWN_MIN"] * w["crown_tree"], "the crown did not move: %s" % w
assert w["foot_edge_max"] <= E["FOOT_EDGE_MAX"] and w["foot_edge_mean"] <= E["FOOT_EDGE_MEAN"], \
    "the foot moved: %s" % w
turn = abs(o["after"]["azimuth"] - o["before"]["azimuth"])
assert turn >= E["TURN_MIN"], "the drag turned the tree by %.3f rad" % turn
# a finger's drag back turns it back: the other way, as far
f0, f1 = o["touch"]
finger = f1["azimuth"] - f0["azimuth"]
assert abs(finger) >= E["TURN_MIN"] and finger * (o["after"]["azimuth"] - o["before"]["azimuth"]) < 0, \
    "a finger's drag turned the tree by %.3f rad" % finger
t = load(r + ".turned")
x0, y0, x1, y1 = t["box"]
assert 0 <= x0 and x1 < t["size"][0] and 0 <= y0 and y1 < t["size"][1] and x1 - x0 > 100, \
    "the turned tree left the window: %s" % t
assert sil["turned"]["iou"] < st["iou"] - 0.1, "turned, the same silhouette: %s" % sil["turned"]
print("%s: ready, no console error, no request; at rest IoU %.3f (>= %.2f), %.3f of the cells "
      "within one (>= %.2f), shapes %.1f%% apart, mean colours %.1f apart (<= %d); in the wind %.3f and %.3f within one; "
      "%.2f s apart the crown's pixels differ %d for its %d, the foot's %d for its %d (its "
      "outline moved %d px at most, %.3f on average); the drag turned it %.2f rad, IoU then %.3f; "
      "a finger's drag back %.2f rad"
      % (r, st["iou"], E["SIL_IOU"], st["near"], E["SIL_NEAR"], 100 * aspect, color,
         E["COLOR_MAX"],
         sil["front"]["near"], sil["later"]["near"], o["seconds"], w["crown_differ"],
         w["crown_tree"], w["foot_differ"], w["foot_tree"], w["foot_edge_max"],
         w["foot_edge_mean"], turn, sil["turned"]["iou"], finger))
PY
done
done
ls -l "$T/demo/model.html" "$T/cherry/model.html" "$T/tree-0012.html" | awk '{print $5, $9}'

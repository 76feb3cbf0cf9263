#!/bin/bash
# SPDX-License-Identifier: MIT
# threejs.sh: the wind in model.glb plays in three.js (Debian 12's libjs-three, r111, and
# its GLTFLoader) in Debian's headless Chromium: the demo in 3D and cherry, exported by the
# edaha binary, loaded from a page with everything inline (threejs_wind.html) and no
# network. Checks what the page found: the animation "wind" (at most 8 s), 10 morph
# targets on the bark and on the leaves, the mixer driving them; the crown's top moving
# between moments, never more than 3% of the tree's height from where it rests, the
# trunk's foot never; the loop's ends equal; two drawn frames differing, not at the foot.
# Paths from meson's environment: EDAHA, DEMO, PAGE, EDAHA_GL_PRELOAD (ASan builds).
# Exit 77 (skipped) without chromium or libjs-three (tools/deps.sh installs both).
set -uo pipefail
: "${EDAHA:?}" "${DEMO:?}" "${PAGE:?}"
THREE=/usr/share/javascript/three
CHROMIUM=$(command -v chromium || command -v chromium-browser) ||
	{ echo "chromium not installed, skipping (Debian: apt-get install chromium)" >&2; exit 77; }
[ -r "$THREE/three.min.js" ] && [ -r "$THREE/examples/js/loaders/GLTFLoader.js" ] ||
	{ echo "libjs-three not installed, skipping (Debian: apt-get install libjs-three)" >&2; exit 77; }
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-threejs.XXXXXX")
trap 'rm -rf "$T"' EXIT
. "$(dirname "$0")/../tools/edaha.sh"
run() {
	edaha --headless "$@" >"$T/log" 2>&1 || { cat "$T/log" >&2; fail "edaha $* exited $?"; }
}

run --out "$T/demo" --replay "$DEMO" --press 3d
run --out "$T/cherry" --press tpl-cherry
for d in demo cherry; do
	python3 - "$PAGE" "$THREE" "$T/$d/model.glb" >"$T/$d.html" <<'PY' || fail "cannot make the page"
import base64, sys
page, three, glb = sys.argv[1:4]
s = open(page).read()
inline = lambda p: "<script>\n" + open(p).read().replace("</script", "<\\/script") + "\n</script>"
s = s.replace("<!-- THREE -->", inline(three + "/three.min.js"))
s = s.replace("<!-- GLTFLOADER -->", inline(three + "/examples/js/loaders/GLTFLoader.js"))
s = s.replace("@MODEL_B64@", base64.b64encode(open(glb, "rb").read()).decode())
sys.stdout.write(s)
PY
	# no network: every request but the page itself goes nowhere
	env -u LD_PRELOAD timeout 120 "$CHROMIUM" --headless=new --no-sandbox --disable-gpu \
		--use-angle=swiftshader --enable-unsafe-swiftshader --no-first-run \
		--user-data-dir="$T/profile" --proxy-server=127.0.0.1:9 --proxy-bypass-list='<-loopback>' \
		--virtual-time-budget=30000 --dump-dom "file://$T/$d.html" >"$T/$d.dom" 2>"$T/$d.err" ||
		{ tail -20 "$T/$d.err" >&2; fail "chromium: $d"; }
	sed -n 's/.*<pre id="out">\(.*\)<\/pre>.*/\1/p' "$T/$d.dom" | python3 -c '
import html, sys
sys.stdout.write(html.unescape(sys.stdin.read()))' >"$T/$d.json"
	python3 - "$T/$d.json" "$d" <<'PY' || { tail -5 "$T/$d.err" >&2; fail "three.js: $d"; }
import json, math, sys
path, name = sys.argv[1:3]
text = open(path).read()
if not text.strip():
    sys.exit("the page wrote nothing")
o = json.loads(text)
if "error" in o:
    sys.exit("the page: %s" % o["error"])
assert o["animations"] == ["wind"], o["animations"]
assert 0 < o["duration"] <= 8.0, o["duration"]
assert len(o["meshes"]) >= 1, o["meshes"]
for m in o["meshes"]:
    assert m["targets"] == 10 and m["relative"], m
    assert m["names"][0] == "wind-trunk-along", m["names"]
assert o["tracks"] == len(o["meshes"]), (o["tracks"], len(o["meshes"]))
ms = o["moments"]
rest_top, rest_foot = ms[0]["top"], ms[0]["foot"]
d = lambda a, b: math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))
height = rest_top[1] - rest_foot[1]
moved = max(d(m["top"], ms[1]["top"]) for m in ms)
assert moved > 1e-3 * height, "the crown's top does not move (%g m)" % moved
for m in ms:
    assert d(m["foot"], rest_foot) < 1e-6, "the foot moved at t %g" % m["t"]
    assert d(m["top"], rest_top) <= 0.03 * height, "the top %.3f m off at t %g" % (d(m["top"], rest_top), m["t"])
    assert any(abs(w) > 0 for w in m["influences"]) or m is ms[0] or m is ms[-1], m
seam = d(ms[0]["top"], ms[-1]["top"])
assert seam < 1e-6, "the loop's ends differ by %g m" % seam
px = o["pixels"]
assert px["tree"] > 100, "nothing drawn: %s" % px
assert px["differ"] > 0, "two moments drew the same picture"
assert 0 <= px["foot"][0] < 256 and 0 <= px["foot"][1] < 256, "the foot is off the picture"
assert px["at_foot"] == 0, "the drawn trunk's foot moved: %s" % px
print("three.js r%s: %s: %d meshes x 10 targets, wind %.2f s, the top moved up to %.1f mm "
      "(%.2f%% of %.1f m), the foot 0, the loop's ends %.1g m apart; drawn: %d of %d tree "
      "pixels differ between t 0.9 and 2.6 s, none round the foot"
      % (o["revision"], name, len(o["meshes"]), o["duration"], moved * 1e3,
         100 * max(d(m["top"], rest_top) for m in ms) / height, height, seam, px["differ"], px["tree"]))
PY
done

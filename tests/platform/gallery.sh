#!/bin/bash
# SPDX-License-Identifier: MIT
# gallery.sh: the stick's index.html (gallery.c, written by gallery_write as a Save
# writes it) opened from file:// in Debian's headless Chromium with the network blocked,
# in English and in Japanese, on a directory as a well-travelled stick holds it: three
# trees with pages (the newest without a picture), one from before pages (its .glb),
# another kiosk's index.html, hostile names, a misspelt set. Checks: no console message
# at all (a blocked load or script would say so), the DOM holds no script and exactly
# the four entries, newest first, every link and picture a file beside the index; in the
# screenshot each picture (a plain colour of its own) is drawn, in that order, left to
# right and top to bottom. Writes the screenshots to $KEEP/ when KEEP is set.
# Paths from meson's environment: GALLERY_WRITE. Exit 77 (skipped) without chromium.
set -uo pipefail
: "${GALLERY_WRITE:?}"
CHROMIUM=$(command -v chromium || command -v chromium-browser) ||
	{ echo "chromium not installed, skipping (Debian: apt-get install chromium)" >&2; exit 77; }
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-gallery.XXXXXX")
trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

d=$T/stick/edaha
mkdir -p "$d"
# the pictures: plain colours, so the screenshot shows which is where
python3 - "$d" <<'PY' || fail "cannot make the pictures"
import struct, sys, zlib
def png(path, rgb, w=320, h=200):
    raw = b"".join(b"\0" + bytes(rgb) * w for _ in range(h))
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
    open(path, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                           + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
d = sys.argv[1]
png(d + "/tree-0001.png", (255, 0, 255))   # from before pages: its .glb is the link
png(d + "/tree-0002.png", (0, 200, 255))
png(d + "/tree-0003.png", (255, 160, 0))
png(d + "/Tree-0005.PNG", (0, 0, 0))       # misspelt: not ours, never shown
PY
page() { printf '<!DOCTYPE html>\n<html><head><meta charset="utf-8"><title>%s</title></head><body></body></html>\n' "$1" > "$d/$1.html"; }
printf 'glTF' > "$d/tree-0001.glb"
for n in 0002 0003 0004; do page "tree-$n"; printf 'glTF' > "$d/tree-$n.glb"; done
printf '<html><body>another kiosk<script>alert(1)</script></body></html>' > "$d/index.html"
for n in '<script>x.glb' 'tree-0001.html"><script>alert(1)' "tree-0002.png' onerror='alert(1)" \
	'a&b.png' 'TREE-0005.HTML' 'tree-6.html' '.tree-0007.html.tmp'; do
	printf 'x' > "$d/$n"
done
printf '<p>half' > "$d/.index.html.tmp" # a stick pulled while the last one was written

for lang in en ja; do
	n=$("$GALLERY_WRITE" "$d" "$lang") || fail "gallery_write $lang"
	[ "$n" = 4 ] || fail "$lang: $n trees listed, not 4"
	[ -e "$d/.index.html.tmp" ] && fail "$lang: the temporary is left"
	# no network: every request but the page's own files goes nowhere
	run() {
		timeout 120 "$CHROMIUM" --headless=new --no-sandbox --disable-gpu --no-first-run \
			--user-data-dir="$T/profile" --proxy-server=127.0.0.1:9 --proxy-bypass-list='<-loopback>' \
			--enable-logging=stderr --v=0 --window-size=1280,1000 --hide-scrollbars "$@" \
			"file://$d/index.html"
	}
	run --dump-dom >"$T/$lang.dom" 2>"$T/$lang.err" || { tail -20 "$T/$lang.err" >&2; fail "chromium: $lang"; }
	run --screenshot="$T/$lang.png" >/dev/null 2>>"$T/$lang.err" || { tail -20 "$T/$lang.err" >&2; fail "chromium: $lang screenshot"; }
	if grep ':CONSOLE' "$T/$lang.err" >&2; then fail "$lang: the console said something"; fi
	python3 - "$T/$lang.dom" "$d" "$T/$lang.png" "$lang" <<'PY' || fail "$lang: the page"
import html.parser, os, struct, sys, zlib
dom, d, shot, lang = sys.argv[1:5]

class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.links, self.pictures, self.tags, self.lang = [], [], set(), None
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.tags.add(tag)
        if tag == "html":
            self.lang = a.get("lang")
        if tag == "a":
            self.links.append(a["href"])
        if tag == "img":
            self.pictures.append(a["src"])
p = Page()
p.feed(open(dom).read())
assert "script" not in p.tags, "a script in the DOM"
assert p.lang == lang, p.lang
want = ["tree-0004.html", "tree-0003.html", "tree-0002.html", "tree-0001.glb"]
assert p.links == want, p.links
assert p.pictures == ["tree-0003.png", "tree-0002.png", "tree-0001.png"], p.pictures
for name in p.links + p.pictures:
    assert os.path.isfile(os.path.join(d, name)), "%s does not resolve" % name

# the screenshot: 8-bit RGB or RGBA, rows unfiltered here
data = open(shot, "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n"
pos, idat = 8, b""
while pos < len(data):
    n, t = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if t == b"IHDR":
        w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
    elif t == b"IDAT":
        idat += body
    pos += 12 + n
assert depth == 8 and ctype in (2, 6), (depth, ctype)
bpp = 3 if ctype == 2 else 4
raw, stride = zlib.decompress(idat), w * bpp
rows, prev = [], bytearray(stride)
for y in range(h):
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - bpp] if i >= bpp else 0
        b, c = prev[i], prev[i - bpp] if i >= bpp else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    rows.append(bytes(line))
    prev = line
colours = {"tree-0003": (255, 160, 0), "tree-0002": (0, 200, 255), "tree-0001": (255, 0, 255)}
where = {}
for name, rgb in colours.items():
    xs, ys = [], []
    for y in range(0, h, 2):
        row = rows[y]
        for x in range(0, w, 2):
            if all(abs(row[x * bpp + k] - rgb[k]) <= 2 for k in range(3)):
                xs.append(x); ys.append(y)
    assert len(xs) > 2000, "%s's picture is not drawn (%d pixels)" % (name, len(xs))
    where[name] = (min(ys), min(xs), len(xs) * 4)
black = sum(1 for y in range(0, h, 2) for x in range(0, w, 2) if rows[y][x * bpp:x * bpp + 3] == b"\0\0\0")
assert black == 0, "the misspelt picture is shown"
order = sorted(where, key=lambda k: (where[k][0] // 20, where[k][1]))  # rows, then columns
assert order == ["tree-0003", "tree-0002", "tree-0001"], "drawn in the order %s" % order
print("gallery %s: 4 entries, newest first, every link and picture a file beside it, no "
      "console message; in a %dx%d screenshot the pictures drawn in order, %s pixels"
      % (lang, w, h, ", ".join("%s %d" % (k, where[k][2]) for k in order)))
PY
	[ -n "${KEEP:-}" ] && cp "$T/$lang.png" "$KEEP/gallery-$lang.png"
done
echo "gallery.sh: OK"

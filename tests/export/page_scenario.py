# SPDX-License-Identifier: MIT
"""What tests/export/page.sh asks of a take-home page, whichever browser shows it
(page_cdp.py: Chromium over the DevTools protocol; page_firefox.py: Firefox over WebDriver
BiDi). Each driver gives four functions; visit() does the rest, the same in both:

  js(expr)        the value of a JavaScript expression in the page (JSON-like)
  shot(path)      a PNG of the page's viewport written to path
  drag(x, y, dx)  a left-button drag from (x, y) to (x + dx, y): press, 12 moves, release
  touch(x, y, dx) the same drag by one finger (None: the driver has no touch)
  pump(seconds)   lets that much time pass, taking the browser's events meanwhile
"""
import os
import sys
import time


def args(argv, doc):
    """PROGRAM BROWSER PAGE.html OUTDIR [--size WxH] [--drag PX]: (browser, page, out, size,
    drag), OUTDIR and OUTDIR/profile made."""
    a = argv[1:]
    size, drag = (1280, 800), 300
    while len(a) > 3:
        if a[-2] == '--size':
            size = tuple(int(v) for v in a[-1].split('x'))
        elif a[-2] == '--drag':
            drag = int(a[-1])
        else:
            break
        a = a[:-2]
    if len(a) != 3:
        sys.exit(doc)
    browser, page, out = a
    os.makedirs(os.path.join(out, 'profile'), exist_ok=True)
    return browser, page, out, size, drag


def visit(result, out, size, drag_px, js, shot, drag, pump, touch=None):
    """Waits for data-state ready or failed (90 s at most) and reads the page's state,
    title, language, label texts and elements into result; when ready: front.png, later.png
    a second on, the drag and turned.png once the damping settled, the finger's drag back
    (result's touch: the views before and after it), then edahaStill() and still.png, with
    edahaView() at each."""
    state = None
    deadline = time.time() + 90
    while time.time() < deadline:
        state = js('document.documentElement && document.documentElement.getAttribute("data-state")')
        if state in ('ready', 'failed'):
            break
        pump(0.2)
    result['state'] = state
    result['title'] = js('document.title')
    result['lang'] = js('document.documentElement.lang')
    result['texts'] = js('[...document.querySelectorAll("#label > div, #note")]'
                         '.map(e => e.hidden ? null : e.textContent)')
    # the document's elements, in order: what the markup (and the viewer) made
    result['elements'] = js('[...document.querySelectorAll("*")].map(e => e.tagName).join(" ")')
    if state != 'ready':
        return
    # the tree alone on the paper
    js('document.getElementById("label").style.visibility = "hidden"')
    pump(0.3)

    def view(name):
        shot(os.path.join(out, name))
        return js('edahaView()')

    v0 = view('front.png')
    t0 = time.time()
    pump(1.0)
    v1 = view('later.png')
    result['seconds'] = time.time() - t0
    result['wind_time'] = [v0['time'], v1['time']]
    result['before'] = v1
    drag(size[0] // 2 - drag_px // 2, size[1] // 2, drag_px)
    pump(2.0)  # the damping settles
    result['after'] = view('turned.png')
    if touch:
        touch(size[0] // 2 + drag_px // 2, size[1] // 2, -drag_px)
        pump(2.0)
        result['touch'] = [result['after'], js('edahaView()')]
    # the tree at rest in the front view, as the kiosk's headless run shows it
    js('edahaStill()')
    pump(0.5)
    result['still'] = view('still.png')

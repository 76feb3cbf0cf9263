#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Opens a take-home page (docs/page.md) in Debian's headless Chromium from a file:// URL,
with every request but the page's own sent to a closed port, and drives it through the
DevTools protocol on a pipe (--remote-debugging-pipe: no socket, no extra module):

  - collects the console (console.error, uncaught exceptions, the browser's own log:
    a CSP refusal, a failed load) and every request the page makes;
  - waits for the page's data-state "ready" (its first frame drawn);
  - screenshots (the label hidden, so only the tree is on the paper): front.png, then
    later.png a second after it;
  - drags across the canvas with synthesised mouse events (press, 12 moves, release) and
    screenshots turned.png once the camera has settled;
  - reads the page's read-only window.edahaView() before and after the drag;
  - stops the wind and shows the front view again through the page's test hook
    edahaStill(): still.png.

usage: page_cdp.py CHROMIUM PAGE.html OUTDIR [--size WxH] [--drag PX]
Writes OUTDIR/{front,later,turned,still}.png and prints one JSON object: errors, requests,
state, title, lang, texts (the label's), elements (every element's tag, in order), view
before/after the drag, and the seconds between the two shots. Exit 0 when it ran (the
caller judges), 1 when Chromium did not.
"""
import base64
import fcntl
import json
import os
import select
import subprocess
import sys
import time

import page_scenario


class Browser:
    def __init__(self, chromium, profile, width, height):
        to_child_r, self.to_child = os.pipe()
        self.from_child, from_child_w = os.pipe()
        # the child's ends above 4, so that making them 3 and 4 moves each once
        to_child_r = self._high(to_child_r)
        from_child_w = self._high(from_child_w)

        # the pipe's ends as fds 3 and 4 (dup2's copies are inheritable; the parent's
        # ends are not: close_fds is not needed and would close these)
        def fds():
            os.dup2(to_child_r, 3)
            os.dup2(from_child_w, 4)

        env = dict(os.environ)
        env.pop('LD_PRELOAD', None)  # an ASan build's GL preload is not Chromium's
        self.proc = subprocess.Popen(
            [chromium, '--headless=new', '--no-sandbox', '--disable-gpu',
             '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-first-run',
             '--no-default-browser-check', '--disable-extensions',
             '--user-data-dir=' + profile,
             # no network: everything but the page itself goes to a closed port
             '--proxy-server=127.0.0.1:9', '--proxy-bypass-list=<-loopback>',
             '--window-size=%d,%d' % (width, height), '--hide-scrollbars',
             '--remote-debugging-pipe', 'about:blank'],
            preexec_fn=fds, close_fds=False, env=env,
            stdout=subprocess.DEVNULL, stderr=open(os.path.join(profile, 'chromium.log'), 'w'))
        os.close(to_child_r)
        os.close(from_child_w)
        self.buf = b''
        self.next_id = 0
        self.events = []

    @staticmethod
    def _high(fd):
        high = fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 10)
        os.close(fd)
        return high

    def close(self):
        try:
            self.call('Browser.close', timeout=10)
        except Exception:
            pass
        try:
            self.proc.wait(10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()

    def _read(self, deadline):
        while b'\0' not in self.buf:
            if time.time() > deadline:
                raise TimeoutError('no answer from chromium')
            r, _, _ = select.select([self.from_child], [], [], max(0.0, deadline - time.time()))
            if not r:
                continue
            chunk = os.read(self.from_child, 1 << 20)
            if not chunk:
                raise EOFError('chromium went away')
            self.buf += chunk
        msg, self.buf = self.buf.split(b'\0', 1)
        return json.loads(msg)

    def call(self, method, params=None, session=None, timeout=60):
        self.next_id += 1
        msg = {'id': self.next_id, 'method': method, 'params': params or {}}
        if session:
            msg['sessionId'] = session
        os.write(self.to_child, json.dumps(msg).encode() + b'\0')
        deadline = time.time() + timeout
        while True:
            m = self._read(deadline)
            if m.get('id') == self.next_id:
                if 'error' in m:
                    raise RuntimeError('%s: %s' % (method, m['error']))
                return m.get('result', {})
            self.events.append(m)

    def pump(self, seconds):
        """Takes the events that come in the next seconds."""
        deadline = time.time() + seconds
        try:
            while True:
                self.events.append(self._read(deadline))
        except TimeoutError:
            pass


def main():
    chromium, page, out, size, drag_px = page_scenario.args(sys.argv, __doc__)
    profile = os.path.join(out, 'profile')
    url = 'file://' + os.path.abspath(page)
    b = Browser(chromium, profile, *size)
    result = {'errors': [], 'requests': [], 'warnings': []}
    try:
        targets = b.call('Target.getTargets')['targetInfos']
        page_target = [t for t in targets if t['type'] == 'page'][0]['targetId']
        s = b.call('Target.attachToTarget', {'targetId': page_target, 'flatten': True})['sessionId']
        for domain in ('Runtime', 'Log', 'Network', 'Page'):
            b.call(domain + '.enable', session=s)
        b.call('Emulation.setDeviceMetricsOverride', {'width': size[0], 'height': size[1],
               'deviceScaleFactor': 1, 'mobile': False}, session=s)
        b.call('Page.navigate', {'url': url}, session=s)

        def js(expr, timeout=60):
            r = b.call('Runtime.evaluate', {'expression': expr, 'returnByValue': True},
                       session=s, timeout=timeout)
            if 'exceptionDetails' in r:
                raise RuntimeError('%s: %s' % (expr, r['exceptionDetails']))
            return r['result'].get('value')

        def shot(path):
            png = b.call('Page.captureScreenshot', {'format': 'png'}, session=s)['data']
            with open(path, 'wb') as f:
                f.write(base64.b64decode(png))

        def drag(x0, y, dx):
            mouse = lambda kind, x, **kw: b.call('Input.dispatchMouseEvent', dict(
                type=kind, x=x, y=y, button='left', clickCount=1, **kw), session=s)
            mouse('mouseMoved', x0, buttons=0)
            mouse('mousePressed', x0, buttons=1)
            for i in range(1, 13):
                mouse('mouseMoved', x0 + dx * i // 12, buttons=1)
                b.pump(0.03)
            mouse('mouseReleased', x0 + dx, buttons=0)

        def touch(x0, y, dx):
            b.call('Emulation.setTouchEmulationEnabled', {'enabled': True, 'maxTouchPoints': 1},
                   session=s)
            finger = lambda kind, pts: b.call('Input.dispatchTouchEvent', dict(
                type=kind, touchPoints=pts), session=s)
            finger('touchStart', [{'x': x0, 'y': y}])
            for i in range(1, 13):
                finger('touchMove', [{'x': x0 + dx * i // 12, 'y': y}])
                b.pump(0.03)
            finger('touchEnd', [])

        page_scenario.visit(result, out, size, drag_px, js, shot, drag, b.pump, touch)
        b.pump(0.2)
    finally:
        b.close()
    for m in b.events:
        meth, p = m.get('method'), m.get('params', {})
        if meth == 'Runtime.consoleAPICalled':
            text = ' '.join(str(a.get('value', a.get('description', ''))) for a in p['args'])
            (result['errors'] if p['type'] in ('error', 'assert') else result['warnings']).append(
                'console.%s: %s' % (p['type'], text))
        elif meth == 'Runtime.exceptionThrown':
            d = p['exceptionDetails']
            result['errors'].append('exception: %s %s' % (
                d.get('text', ''), d.get('exception', {}).get('description', '')))
        elif meth == 'Log.entryAdded':
            e = p['entry']
            if e['level'] == 'error':
                result['errors'].append('log (%s): %s' % (e['source'], e['text']))
            else:
                result['warnings'].append('log (%s): %s' % (e['source'], e['text']))
        elif meth == 'Network.requestWillBeSent':
            if p['request']['url'] != url:
                result['requests'].append(p['request']['url'][:200])
    print(json.dumps(result))


if __name__ == '__main__':
    main()

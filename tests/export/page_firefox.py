#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Opens a take-home page (docs/page.md) in Debian's Firefox ESR, headless, from a file://
URL, with every request but the page's own sent to a closed port, and drives it through
WebDriver BiDi (Firefox's own remote protocol, a WebSocket: spoken here with the standard
library alone). What page_cdp.py does in Chromium, with the same outputs, so that page.sh
judges both browsers alike:

  - collects the log (console.error, uncaught exceptions) and every request the page makes;
  - waits for the page's data-state "ready" (its first frame drawn);
  - screenshots (the label hidden): front.png, later.png a second after it;
  - drags across the canvas (pointer actions: press, 12 moves, release) and screenshots
    turned.png once the camera has settled;
  - reads window.edahaView() before and after the drag;
  - edahaStill(): the front view at rest, still.png.

Firefox's WebGL needs a display even when headless: the caller gives DISPLAY (Xvfb).

usage: page_firefox.py FIREFOX PAGE.html OUTDIR [--size WxH] [--drag PX]
Prints one JSON object as page_cdp.py does. Exit 0 when it ran (the caller judges), 1 when
Firefox did not.
"""
import base64
import json
import os
import re
import select
import socket
import struct
import subprocess
import sys
import time

import page_scenario

PREFS = """
user_pref("webgl.force-enabled", true);
user_pref("network.proxy.type", 1);
user_pref("network.proxy.http", "127.0.0.1");
user_pref("network.proxy.http_port", 9);
user_pref("network.proxy.ssl", "127.0.0.1");
user_pref("network.proxy.ssl_port", 9);
user_pref("network.proxy.allow_hijacking_localhost", true);
user_pref("browser.shell.checkDefaultBrowser", false);
user_pref("datareporting.policy.dataSubmissionEnabled", false);
user_pref("toolkit.telemetry.reportingpolicy.firstRun", false);
user_pref("app.update.disabledForTesting", true);
user_pref("browser.startup.homepage_override.mstone", "ignore");
user_pref("remote.prefs.recommended", true);
"""


class WebSocket:
    """A client WebSocket (RFC 6455): text frames, masked as a client's must be."""

    def __init__(self, host, port, path):
        self.sock = socket.create_connection((host, port), timeout=30)
        key = base64.b64encode(os.urandom(16)).decode()
        self.sock.sendall(('GET %s HTTP/1.1\r\nHost: %s:%d\r\nUpgrade: websocket\r\n'
                           'Connection: Upgrade\r\nSec-WebSocket-Key: %s\r\n'
                           'Sec-WebSocket-Version: 13\r\n\r\n' % (path, host, port, key)).encode())
        head = b''
        while b'\r\n\r\n' not in head:
            chunk = self.sock.recv(4096)
            if not chunk:
                raise EOFError('the WebSocket closed in its handshake')
            head += chunk
        head, self.buf = head.split(b'\r\n\r\n', 1)
        if b' 101 ' not in head.split(b'\r\n', 1)[0]:
            raise RuntimeError('no WebSocket: %r' % head[:200])

    def send(self, text):
        data = text.encode()
        n = len(data)
        head = bytes([0x81])
        if n < 126:
            head += bytes([0x80 | n])
        elif n < 1 << 16:
            head += bytes([0x80 | 126]) + struct.pack('>H', n)
        else:
            head += bytes([0x80 | 127]) + struct.pack('>Q', n)
        mask = os.urandom(4)
        body = bytes(b ^ mask[i % 4] for i, b in enumerate(data))
        self.sock.sendall(head + mask + body)

    def _need(self, n, deadline):
        while len(self.buf) < n:
            left = deadline - time.time()
            if left <= 0:
                raise TimeoutError
            r, _, _ = select.select([self.sock], [], [], left)
            if not r:
                continue
            chunk = self.sock.recv(1 << 20)
            if not chunk:
                raise EOFError('firefox went away')
            self.buf += chunk

    def recv(self, deadline):
        """One whole message (fragments joined), or TimeoutError."""
        parts = []
        while True:
            self._need(2, deadline)
            b0, b1 = self.buf[0], self.buf[1]
            n, at = b1 & 0x7f, 2
            if n == 126:
                self._need(4, deadline)
                n, at = struct.unpack('>H', self.buf[2:4])[0], 4
            elif n == 127:
                self._need(10, deadline)
                n, at = struct.unpack('>Q', self.buf[2:10])[0], 10
            if b1 & 0x80:
                at += 4  # a server never masks; skip a mask all the same
            self._need(at + n, deadline)
            payload, self.buf = self.buf[at:at + n], self.buf[at + n:]
            op = b0 & 0x0f
            if op == 8:
                raise EOFError('firefox closed the WebSocket')
            if op in (9, 10):
                continue  # ping, pong
            parts.append(payload)
            if b0 & 0x80:
                return b''.join(parts).decode()


class Firefox:
    def __init__(self, firefox, profile, log):
        with open(os.path.join(profile, 'user.js'), 'w') as f:
            f.write(PREFS)
        env = dict(os.environ)
        env.pop('LD_PRELOAD', None)  # an ASan build's GL preload is not Firefox's
        env['MOZ_HEADLESS'] = '1'
        self.log = open(log, 'w+')
        self.proc = subprocess.Popen(
            [firefox, '--headless', '--no-remote', '--profile', profile,
             '--remote-debugging-port', '0', 'about:blank'],
            env=env, stdout=self.log, stderr=subprocess.STDOUT)
        port = None
        deadline = time.time() + 60
        while port is None and time.time() < deadline:
            if self.proc.poll() is not None:
                raise RuntimeError('firefox exited %d' % self.proc.returncode)
            self.log.seek(0)
            m = re.search(r'WebDriver BiDi listening on ws://127\.0\.0\.1:(\d+)', self.log.read())
            if m:
                port = int(m.group(1))
            else:
                time.sleep(0.1)
        if port is None:
            raise RuntimeError('firefox never listened')
        self.ws = WebSocket('127.0.0.1', port, '/session')
        self.next_id = 0
        self.events = []

    def call(self, method, params=None, timeout=60):
        self.next_id += 1
        self.ws.send(json.dumps({'id': self.next_id, 'method': method, 'params': params or {}}))
        deadline = time.time() + timeout
        while True:
            m = json.loads(self.ws.recv(deadline))
            if m.get('id') == self.next_id:
                if m.get('type') == 'error':
                    raise RuntimeError('%s: %s %s' % (method, m.get('error'), m.get('message')))
                return m.get('result', {})
            self.events.append(m)

    def pump(self, seconds):
        deadline = time.time() + seconds
        try:
            while True:
                self.events.append(json.loads(self.ws.recv(deadline)))
        except TimeoutError:
            pass

    def close(self):
        try:
            self.call('browser.close', timeout=10)
        except Exception:
            pass
        try:
            self.proc.wait(15)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


def main():
    firefox, page, out, size, drag_px = page_scenario.args(sys.argv, __doc__)
    profile = os.path.join(out, 'profile')
    url = 'file://' + os.path.abspath(page)
    try:
        b = Firefox(firefox, profile, os.path.join(out, 'firefox.log'))
    except Exception as e:
        print('page_firefox: %s' % e, file=sys.stderr)
        sys.exit(1)
    result = {'errors': [], 'requests': [], 'warnings': []}
    try:
        b.call('session.new', {'capabilities': {}})
        b.call('session.subscribe', {'events': ['log.entryAdded', 'network.beforeRequestSent']})
        ctx = b.call('browsingContext.getTree')['contexts'][0]['context']
        b.call('browsingContext.setViewport', {'context': ctx, 'viewport': {
               'width': size[0], 'height': size[1]}, 'devicePixelRatio': 1})
        b.call('browsingContext.navigate', {'context': ctx, 'url': url, 'wait': 'complete'},
               timeout=120)

        def js(expr, timeout=60):
            r = b.call('script.evaluate', {
                'expression': 'JSON.stringify((() => %s)())' % expr,
                'target': {'context': ctx}, 'awaitPromise': False}, timeout=timeout)
            if r.get('type') == 'exception':
                raise RuntimeError('%s: %s' % (expr, r['exceptionDetails'].get('text')))
            v = r['result']
            return json.loads(v['value']) if v.get('type') == 'string' else None

        def shot(path):
            png = b.call('browsingContext.captureScreenshot', {'context': ctx})['data']
            with open(path, 'wb') as f:
                f.write(base64.b64decode(png))

        def pointer_drag(kind, x0, y, dx):
            moves = [{'type': 'pointerMove', 'x': x0, 'y': y},
                     {'type': 'pointerDown', 'button': 0}]
            for i in range(1, 13):
                moves.append({'type': 'pointerMove', 'x': x0 + dx * i // 12, 'y': y,
                              'duration': 30})
            moves.append({'type': 'pointerUp', 'button': 0})
            b.call('input.performActions', {'context': ctx, 'actions': [{
                   'type': 'pointer', 'id': kind, 'parameters': {'pointerType': kind},
                   'actions': moves}]})

        drag = lambda x0, y, dx: pointer_drag('mouse', x0, y, dx)
        touch = lambda x0, y, dx: pointer_drag('touch', x0, y, dx)

        page_scenario.visit(result, out, size, drag_px, js, shot, drag, b.pump, touch)
        b.pump(0.2)
    except Exception as e:
        result['errors'].append('driver: %s' % e)
    finally:
        b.close()
    for m in b.events:
        meth, p = m.get('method'), m.get('params', {})
        if meth == 'log.entryAdded':
            text = p.get('text') or ' '.join(str(a.get('value', '')) for a in p.get('args', []))
            kind = p.get('type') if p.get('type') != 'console' else 'console.' + p.get('method', '')
            (result['errors'] if p.get('level') == 'error' else result['warnings']).append(
                '%s: %s' % (kind, text))
        elif meth == 'network.beforeRequestSent':
            u = p.get('request', {}).get('url', '')
            if u != url:
                result['requests'].append(u[:200])
    print(json.dumps(result))


if __name__ == '__main__':
    main()

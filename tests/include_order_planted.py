#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The include-order test can fail (issue 25): on a copy of src/, an upward include
(core's tree.c including the app's app.h) and a sideways one (sketch's lift.c including
vine.h, a system on the same floor) must each make include_order.py fail and name the file
and line; the untouched copy must pass.

usage: include_order_planted.py INCLUDE_ORDER_PY SRC_DIR
"""
import os
import shutil
import subprocess
import sys
import tempfile


def run(checker, src):
    p = subprocess.run([sys.executable, checker, src], capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def plant(src, rel, header):
    path = os.path.join(src, rel)
    with open(path, encoding='utf-8') as f:
        lines = f.read().split('\n')
    # after the first include, so the line number is known
    at = next(i for i, l in enumerate(lines) if l.startswith('#include'))
    lines.insert(at + 1, '#include "%s"' % header)
    with open(path, 'w', encoding='utf-8') as f:
        f.write('\n'.join(lines))
    return at + 2


def main():
    checker, src = sys.argv[1], sys.argv[2]
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        clean = os.path.join(tmp, 'clean')
        shutil.copytree(src, clean)
        rc, out = run(checker, clean)
        if rc != 0:
            print('FAIL: the untouched copy does not pass:\n' + out)
            failures += 1
        for name, rel, header in (('upward', 'core/tree.c', 'app.h'),
                                  ('sideways', 'sketch/lift.c', 'vine.h')):
            copy = os.path.join(tmp, name)
            shutil.copytree(src, copy)
            line = plant(copy, rel, header)
            rc, out = run(checker, copy)
            where = '%s:%d' % (rel, line)
            if rc == 0 or where not in out:
                print('FAIL: a planted %s include (%s: "%s") was not caught as %s:\n%s'
                      % (name, rel, header, where, out))
                failures += 1
            else:
                hit = next(l for l in out.splitlines() if where in l)
                print('caught the planted %s include: %s' % (name, hit.strip()))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())

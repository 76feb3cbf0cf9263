#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""No circles between src/'s systems (issue 25): every #include "..." in a file under
src/ names a header of the file's own system or of a lower floor, as src/FLOORS sets
them out; two systems on one floor do not include each other. Fails on an upward or
sideways include, on a quoted include that is no file under src/, on a file under src/
the table does not place or that is not in its system's folder (src/SYSTEM/), and on a
name in the table that places no file.

usage: include_order.py SRC_DIR [FLOORS]   (FLOORS defaults to SRC_DIR/FLOORS)
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def read_floors(path):
    """{name: (floor, system)} and [(prefix, floor, system)] from the table."""
    exact, prefixes, errors = {}, [], []
    floor = system = None
    with open(path, encoding='utf-8') as f:
        for lineno, line in enumerate(f, 1):
            line = line.split('#', 1)[0].rstrip()
            if not line.strip():
                continue
            words = line.split()
            if not line[0].isspace():  # a new row: floor, system, names
                if len(words) < 2 or not words[0].isdigit():
                    errors.append(f'{path}:{lineno}: expected "FLOOR SYSTEM NAME..."')
                    continue
                floor, system, words = int(words[0]), words[1], words[2:]
            elif floor is None:
                errors.append(f'{path}:{lineno}: names before the first row')
                continue
            for w in words:
                if w.endswith('*'):
                    prefixes.append((w[:-1], floor, system))
                elif w in exact:
                    errors.append(f'{path}:{lineno}: {w} is placed twice')
                else:
                    exact[w] = (floor, system)
    return exact, prefixes, errors


def place(name, exact, prefixes):
    """The (floor, system) of a file name, or None."""
    stem = os.path.splitext(name)[0]
    if stem in exact:
        return exact[stem]
    best = None
    for prefix, floor, system in prefixes:
        if stem.startswith(prefix) and (best is None or len(prefix) > len(best[0])):
            best = (prefix, floor, system)
    return best[1:] if best else None


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    src = sys.argv[1]
    table = sys.argv[2] if len(sys.argv) == 3 else os.path.join(src, 'FLOORS')
    exact, prefixes, errors = read_floors(table)

    files = {}  # name -> path
    for root, _, names in os.walk(src):
        for n in names:
            if n.endswith(('.c', '.h')):
                if n in files:
                    errors.append(f'{n}: two files of that name ({files[n]}, {root})')
                files[n] = os.path.join(root, n)

    placed, used = {}, set()
    for n in sorted(files):
        where = place(n, exact, prefixes)
        if where is None:
            errors.append(f'{files[n]}: not placed on a floor in {table}')
        else:
            placed[n] = where
            used.add(os.path.splitext(n)[0])
            folder = os.path.relpath(os.path.dirname(files[n]), src)
            if folder != where[1]:
                errors.append(f'{files[n]}: of {where[1]}, not in src/{where[1]}/')
    for name in sorted(exact):
        if name not in used:
            errors.append(f'{table}: {name} places no file under {src}')

    edges = 0
    per_floor = {}
    for n in sorted(placed):
        floor, system = placed[n]
        per_floor.setdefault((floor, system), 0)
        per_floor[(floor, system)] += 1
        with open(files[n], encoding='utf-8') as f:
            for lineno, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                target = os.path.basename(m.group(1))
                where = f'{files[n]}:{lineno}'
                if target not in files:
                    errors.append(f'{where}: includes "{m.group(1)}", no file under {src}')
                    continue
                if target not in placed:
                    continue  # reported above
                edges += 1
                tfloor, tsystem = placed[target]
                if tsystem == system:
                    continue
                if tfloor > floor:
                    errors.append(f'{where}: {system} (floor {floor}) includes {target}, '
                                  f'{tsystem} (floor {tfloor}): upward')
                elif tfloor == floor:
                    errors.append(f'{where}: {system} includes {target} of {tsystem}, '
                                  f'beside it on floor {floor}')

    for (floor, system), count in sorted(per_floor.items()):
        print(f'floor {floor} {system}: {count} files')
    print(f'{len(placed)} files placed, {edges} includes between src files checked, '
          f'{len(errors)} problems')
    for e in errors:
        print('FAIL:', e)
    return 1 if errors else 0


if __name__ == '__main__':
    sys.exit(main())

#!/usr/bin/env python3
# test_layers.py NM LIBEDAHA_UI.A: the renderer's files call one another one way only.
#
# From the symbols each object of ui's library defines and uses (nm): the frame (render.c)
# is the top, which no other file calls back into; the GL helpers (gl/render_gl.c) and the
# lit programs' sources (gl/render_shaders.c) are the bottom, which call no other file of
# ui's; and no files call each other round in a circle. Prints the files floor by floor.
import re
import subprocess
import sys

TOP = "render"
BOTTOM = ("gl/render_gl", "gl/render_shaders")
# ui's folders: meson names the object of gl/batch.c gl_batch.c.o
FOLDERS = ("gl", "text")


def source(obj):
    """The source's path in ui/ (without .c) of an object's name."""
    for folder in FOLDERS:
        if obj.startswith(folder + "_"):
            return folder + "/" + obj[len(folder) + 1:]
    return obj


def symbols(nm, archive):
    """{object: (defined globals, undefined)} of each object in the archive."""
    out = subprocess.run([nm, "-A", "-P", archive], check=True, capture_output=True,
                         text=True).stdout
    objs = {}
    for line in out.splitlines():
        m = re.match(r"^.*\[(?:.*/)?([^/\]]+)\.c\.o\]: (\S+) (\S)", line)
        if not m:
            continue
        obj, name, kind = m.groups()
        obj = source(obj)
        defined, used = objs.setdefault(obj, (set(), set()))
        if kind == "U":
            used.add(name)
        elif kind.isupper():
            defined.add(name)
    return objs


def uses(objs):
    """{object: {object it calls: [symbols]}} within the archive."""
    owner = {name: obj for obj, (defined, _) in objs.items() for name in defined}
    edges = {obj: {} for obj in objs}
    for obj, (_, used) in objs.items():
        for name in sorted(used):
            if name in owner and owner[name] != obj:
                edges[obj].setdefault(owner[name], []).append(name)
    return edges


def floors(edges):
    """Each object's floor (0: calls no other; else one above the highest it calls), or
    None and a circle."""
    floor, state = {}, {}

    def visit(obj, path):
        if state.get(obj) == "done":
            return None
        if state.get(obj) == "open":
            return path[path.index(obj):] + [obj]
        state[obj] = "open"
        for callee in sorted(edges[obj]):
            circle = visit(callee, path + [obj])
            if circle:
                return circle
        floor[obj] = 1 + max((floor[c] for c in edges[obj]), default=-1)
        state[obj] = "done"
        return None

    for obj in sorted(edges):
        circle = visit(obj, [])
        if circle:
            return None, circle
    return floor, None


def main():
    nm, archive = sys.argv[1], sys.argv[2]
    objs = symbols(nm, archive)
    edges = uses(objs)
    bad = []
    for need in (TOP,) + BOTTOM:
        if need not in objs:
            bad.append(f"no {need}.c.o in {archive}")
    for obj in sorted(edges):
        if TOP in edges[obj]:
            bad.append(f"{obj}.c calls back into {TOP}.c: {', '.join(edges[obj][TOP])}")
    for obj in BOTTOM:
        for callee, names in sorted(edges.get(obj, {}).items()):
            bad.append(f"{obj}.c (the bottom) calls {callee}.c: {', '.join(names)}")
    floor, circle = floors(edges)
    if circle:
        bad.append("a circle: " + " -> ".join(f"{o}.c" for o in circle))
    else:
        for f in range(max(floor.values()) + 1):
            print(f"floor {f}: " + " ".join(sorted(f"{o}.c" for o in floor if floor[o] == f)))
        print(f"{len(objs)} files, {sum(len(e) for e in edges.values())} one-way calls between them")
    for line in bad:
        print("test_layers.py: " + line)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())

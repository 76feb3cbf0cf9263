#!/usr/bin/env python3
"""The pen strokes of an edaha trace as an xdotool script: trace2xdo.py TRACE WINDOW [SCALE].

The pen's positions, times SCALE (the window's size over the trace's screen), become the
pointer's, relative to the X window WINDOW; tip-down and
tip-up the left button. Hover motion is kept (the pen over the canvas), proximity-out
takes the pointer off the window's picture, pressure is dropped (a mouse has none)."""
import sys


def main():
    trace, window = sys.argv[1], sys.argv[2]
    scale = float(sys.argv[3]) if len(sys.argv) > 3 else 1.0
    out = []
    with open(trace, encoding="utf-8") as f:
        for line in f:
            w = line.split()
            if not w or w[0].startswith("#") or not w[0].isdigit() or len(w) < 5:
                continue
            kind = w[1]
            if kind not in ("proximity-in", "motion", "tip-down", "tip-up"):
                continue
            x, y = round(float(w[3]) * scale), round(float(w[4]) * scale)
            out.append(f"mousemove --window {window} {x} {y}")
            if kind == "tip-down":
                out.append("mousedown 1")
            elif kind == "tip-up":
                out.append("mouseup 1")
            # a pen's pace, so that the events are not merged into fewer
            out.append("sleep 0.004")
    if not any(c == "mousedown 1" for c in out):
        sys.exit(f"{trace}: no strokes")
    print("\n".join(out))


main()

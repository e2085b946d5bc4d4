#!/usr/bin/env python3
"""A full solution of examples/assignments/dda-2d/dda2d.py (not shipped: tests only), and the named
mistakes of docs/assignment-format.md it can make on purpose:

    python3 dda2d_solution.py [rays.json] [--mistake NAME] > walk.jsonl

Everything above "end of the given code" is the kit's, byte for byte (the test checks it).
"""
import argparse
import json
import math
import os
import sys

INF = math.inf

# ---- Given: the log (one JSON object a line, on stdout) ----

cells_logged = 0


def _number(v):
    # JSON has no Infinity: an infinite tMax (an axis the ray is parallel to) is logged as null.
    return v if math.isfinite(v) else None


def log_ray(origin, direction):
    print(json.dumps({"ray": {"origin": list(origin), "dir": list(direction)}}))


def log_cell(cell, tmax=None):
    """Log a cell the walk visits, [X, Y]; tmax, optional, is [tMaxX, tMaxY] in that cell."""
    global cells_logged
    for c in cell:
        if c != int(c):
            raise ValueError("log_cell(%r): a cell's indices are whole numbers" % (cell,))
    cells_logged += 1
    record = {"cell": [int(c) for c in cell]}
    if tmax is not None:
        record["tMax"] = [_number(float(t)) for t in tmax]
    print(json.dumps(record, allow_nan=False))


# ---- Given: the rays to run (rays.json) ----


def read_rays(path):
    """The grid (res, lo, hi) and the rays, each {"origin": [x, y], "dir": [dx, dy]}."""
    with open(path) as f:
        data = json.load(f)  # reads -0.0 as -0.0: the sign of a zero matters (TASK.md)
    grid = data["grid"]
    return grid["res"], grid["min"], grid["max"], data["rays"]


def default_rays():
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "rays.json")

# ---- end of the given code ----

# ---- The solution ----

MISTAKES = (
    "start-cell-skipped",
    "negative-direction-boundary",
    "parallel-axis-division",
    "negative-zero",
    "tie-one-axis",
    "no-entry-clip",
    "no-exit-check",
)
# no-exit-check: the walk goes on past the grid for this many cells, so that it ends.
CELLS_BEYOND = 64



def ieee_div(a, b):
    """a / b as C computes it: Python raises on b = 0, a mistaken walk divides by zero."""
    if b != 0:
        return a / b
    if a == 0 or math.isnan(a):
        return math.nan
    return math.copysign(INF, a) * math.copysign(1.0, b)


def walk(res, lo, hi, o, d, mistake=None):
    """Log every cell the ray o + t d (t >= 0) visits, from where it enters the grid to where it
    leaves it."""
    n = len(res)
    VSize = [(hi[i] - lo[i]) / res[i] for i in range(n)]

    # Where the ray enters the grid (slab by slab); a zero component is parallel to that axis.
    tEnter, tExit = 0.0, INF
    for i in range(n):
        if d[i] == 0:
            if o[i] < lo[i] or o[i] > hi[i]:
                return
            continue
        t0, t1 = (lo[i] - o[i]) / d[i], (hi[i] - o[i]) / d[i]
        if t0 > t1:
            t0, t1 = t1, t0
        tEnter, tExit = max(tEnter, t0), min(tExit, t1)
    if not tEnter < tExit:
        return  # misses the grid, or only touches it

    step, X, tMax = [0] * n, [0] * n, [INF] * n
    for i in range(n):
        if mistake == "parallel-axis-division":
            step[i] = 1 if d[i] > 0 else -1
        elif mistake == "negative-zero":
            step[i] = 1 if d[i] >= 0 else -1
        else:
            step[i] = 1 if d[i] > 0 else (-1 if d[i] < 0 else 0)
        if mistake == "no-entry-clip":
            p = o[i]
        else:
            p = o[i] + tEnter * d[i]
        # The cell the ray goes into: on a boundary moving down, the one below it.
        if step[i] < 0 and mistake != "no-entry-clip":
            X[i] = math.ceil((p - lo[i]) / VSize[i]) - 1
        else:
            X[i] = math.floor((p - lo[i]) / VSize[i])
        X[i] = min(max(X[i], 0), res[i] - 1)

    tDelta = [INF] * n
    for i in range(n):
        if step[i] != 0:
            # The first boundary ahead: X + 1 moving up, X moving down.
            k = X[i] + 1 if step[i] > 0 or mistake == "negative-direction-boundary" else X[i]
            tMax[i] = ieee_div(lo[i] + k * VSize[i] - o[i], d[i])
            tDelta[i] = ieee_div(VSize[i], abs(d[i]))

    beyond = 0
    first = True
    while True:
        if not (first and mistake == "start-cell-skipped"):
            log_cell(X, tMax)
        first = False
        # The axis of the smallest tMax, by the slides' comparison (the later axis at a tie).
        a = 0
        for i in range(1, n):
            if not tMax[a] < tMax[i]:
                a = i
        t = tMax[a]
        if t == INF:
            break  # no boundary ahead on any axis (a zero direction)
        out = False
        for i in range(n):
            # At an exact tie every tied axis steps (tie-one-axis: the slides' one, a).
            if i == a or (mistake != "tie-one-axis" and tMax[i] == t):
                X[i] += step[i]
                tMax[i] += tDelta[i]  # the slides' tMaxX += tDeltaX
                out = out or not 0 <= X[i] < res[i]
        if out:
            if mistake != "no-exit-check":
                break
            beyond += 1
            if beyond > CELLS_BEYOND:
                break


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rays", nargs="?", default=default_rays())
    parser.add_argument("--mistake", choices=MISTAKES)
    args = parser.parse_args()
    res, lo, hi, rays = read_rays(args.rays)
    for ray in rays:
        log_ray(ray["origin"], ray["dir"])
        walk(res, lo, hi, ray["origin"], ray["dir"], args.mistake)


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""The lecture's 2D DDA (Amanatides & Woo 1987): the cells a ray visits on a regular grid, logged
as JSON Lines for raystep to check. Write walk() (the TODOs); the rest is given.

    python3 dda2d.py > walk.jsonl
    raystep-cli assess dda --grid 8,6 --min 0,0 --max 8,6 --trace walk.jsonl

The rays come from rays.json next to this file (or the file named on the command line). TASK.md
says what the walk must do and how to read raystep's verdict.
"""
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

# ---- Your walk ----


def walk(res, lo, hi, o, d):
    """Log, in order, every cell the ray o + t d (t >= 0) visits on the grid of res[0] x res[1]
    cells over [lo, hi]: from the cell where the ray enters the grid to the one where it leaves
    it. A ray that misses the grid logs no cell."""
    # The size of a cell along each axis: the slides' VSizeX, VSizeY.
    VSizeX = (hi[0] - lo[0]) / res[0]
    VSizeY = (hi[1] - lo[1]) / res[1]

    # TODO 1. Where the ray enters the grid: tEnter = 0 if the origin is inside, else the t where
    # it crosses into the grid's box (the slab test, axis by axis); and tExit, where it leaves.
    # A ray that misses the box, or only touches it (tEnter >= tExit), visits no cell: return.
    # A zero component of d (0.0 or -0.0) is parallel to that axis: no slab crossing there (and
    # in Python x / 0.0 raises ZeroDivisionError: test for zero first).

    # TODO 2. The set-up, per axis (X shown; Y alike):
    #   stepX   = +1, -1, or 0 when dx is zero (the ray never crosses an X boundary);
    #   X       = the cell of the entry point o + tEnter d (if that point lies exactly on a
    #             boundary, the cell the ray goes into: the lower one when stepX = -1);
    #   tMaxX   = the t of the first X boundary ahead: boundary X + 1 when stepX = +1, boundary X
    #             when stepX = -1, INF when stepX = 0;
    #   tDeltaX = VSizeX / abs(dx), the t between two X boundaries.

    # TODO 3. The loop: log the cell, log_cell([X, Y], [tMaxX, tMaxY]), then step across the
    # smaller tMax (tMaxX += tDeltaX, X += stepX, as in the slides). At an exact tie step both
    # axes at once: the ray goes through a grid vertex and only touches the two cells beside it.
    # Stop when a step leaves the grid.


def main():
    res, lo, hi, rays = read_rays(sys.argv[1] if len(sys.argv) > 1 else default_rays())
    for ray in rays:
        log_ray(ray["origin"], ray["dir"])
        walk(res, lo, hi, ray["origin"], ray["dir"])
    if cells_logged == 0:
        # Not a finished walk: every kit's ray list has rays that visit cells.
        print("dda2d.py: walk() logged no cell: write its TODOs (TASK.md)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

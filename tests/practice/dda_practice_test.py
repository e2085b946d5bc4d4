#!/usr/bin/env python3
"""Independent check of the dda-2d and dda-3d practice generators (docs/practice.md).

Every answer of `raystep-cli practice make TOPIC --seed S --level L --json` is recomputed here
from its `given` data in exact fractions, with a DDA written from Amanatides & Woo's paper and
no raystep code: tDelta, tMax at the set-up, the first cell (also from outside), the next cell
and the walk until the ray leaves the grid; an exact tie steps every tied axis at once. The level
rules are checked too, the same seed gives the same bytes, and instances rarely repeat.

usage: dda_practice_test.py RAYSTEP_CLI [SEEDS]
"""
import json
import math
import subprocess
import sys
import tempfile
from fractions import Fraction as F

CLI = sys.argv[1]
SEEDS = int(sys.argv[2]) if len(sys.argv) > 2 else 120
failures = []


def fail(where, message):
    failures.append(f"{where}: {message}")


def make(topic, seed, level):
    out = subprocess.run([CLI, "practice", "make", topic, "--seed", str(seed), "--level", level,
                          "--json"], capture_output=True, check=True)
    return out.stdout


def exact(x):
    # The JSON number as written: the decimal the student reads (ties are drawn only in
    # binary-exact numbers, and other draws keep 0.05 between crossings, so both agree).
    return F(repr(x)) if isinstance(x, float) else F(x)


def walk(g):
    n = len(g["grid"])
    lo = [exact(v) for v in g["min"]]
    hi = [exact(v) for v in g["max"]]
    o = [exact(v) for v in g["origin"]]
    d = [exact(v) for v in g["dir"]]
    res = g["grid"]
    size = [(hi[a] - lo[a]) / res[a] for a in range(n)]
    t_enter, t_exit = F(0), None
    for a in range(n):
        t0, t1 = (lo[a] - o[a]) / d[a], (hi[a] - o[a]) / d[a]
        if t0 > t1:
            t0, t1 = t1, t0
        t_enter = max(t_enter, t0)
        t_exit = t1 if t_exit is None else min(t_exit, t1)
    assert t_enter < t_exit, "the ray misses the grid"
    cell = []
    for a in range(n):
        u = (o[a] + t_enter * d[a] - lo[a]) / size[a]
        k = math.floor(u)
        if u == k and d[a] < 0:
            k -= 1  # on a boundary, the cell the ray moves into
        cell.append(min(max(k, 0), res[a] - 1))
    t_max = [(lo[a] + (cell[a] + (1 if d[a] > 0 else 0)) * size[a] - o[a]) / d[a]
             for a in range(n)]
    t_delta = [size[a] / abs(d[a]) for a in range(n)]
    first_t_max = list(t_max)
    cells, ties = [list(cell)], 0
    while True:
        m = min(t_max)
        if m >= t_exit:
            break
        tied = [a for a in range(n) if t_max[a] == m]
        ties += len(tied) > 1
        for a in tied:
            cell[a] += 1 if d[a] > 0 else -1
            t_max[a] += t_delta[a]
        if any(c < 0 or c >= r for c, r in zip(cell, res)):
            break
        cells.append(list(cell))
    return {"tDelta": t_delta, "tMax": first_t_max, "cells": cells, "ties": ties,
            "inside": t_enter == 0}


def close(a, b):
    return abs(a - b) <= 1e-9 * max(1.0, abs(b))


for topic in ("dda-2d", "dda-3d"):
    for level in ("easy", "medium", "hard"):
        seen = set()
        outside = 0
        for seed in range(1, SEEDS + 1):
            where = f"{topic} {level} seed {seed}"
            raw = make(topic, seed, level)
            p = json.loads(raw)
            g, ans = p["given"], p["answers"]
            seen.add(json.dumps(g, sort_keys=True))
            if p["format"] != "raystep-practice" or p["topic"] != topic or p["seed"] != seed:
                fail(where, "the header does not name the instance")
            ref = walk(g)
            for name in ("tDelta", "tMax"):
                for a, (got, want) in enumerate(zip(ans[name], ref[name])):
                    if not close(got, float(want)):
                        fail(where, f"{name}[{a}] = {got}, recomputed {float(want)}")
            if ans["firstCell"] != ref["cells"][0]:
                fail(where, f"firstCell {ans['firstCell']}, recomputed {ref['cells'][0]}")
            if ans["nextCell"] != ref["cells"][1]:
                fail(where, f"nextCell {ans['nextCell']}, recomputed {ref['cells'][1]}")
            if ans["walk"] != ref["cells"]:
                fail(where, f"walk {ans['walk']}, recomputed {ref['cells']}")
            # The level's rules.
            most = {"easy": 6, "medium": 8, "hard": 9}[level]
            if not 3 <= len(ref["cells"]) <= most:
                fail(where, f"a walk of {len(ref['cells'])} cells")
            if level == "easy" and (not ref["inside"] or min(g["dir"]) <= 0):
                fail(where, "easy: the ray starts inside and goes towards +x, +y")
            if level == "hard" and ref["ties"] == 0:
                fail(where, "hard: no tie through a grid vertex")
            if level != "hard" and ref["ties"] > 0:
                fail(where, f"{level}: a tie")
            if any(v == 0 for v in g["dir"]):
                fail(where, "a direction component is zero")
            outside += not ref["inside"]
            if seed <= 3 and make(topic, seed, level) != raw:
                fail(where, "the same seed gave different bytes")
        if len(seen) < 0.9 * SEEDS:
            fail(f"{topic} {level}", f"only {len(seen)} distinct instances in {SEEDS}")
        if level != "easy" and outside == 0:
            fail(f"{topic} {level}", "no ray from outside the grid")

# The lesson file (-o) is one `lesson validate` takes, and its key scores full marks.
with tempfile.TemporaryDirectory() as tmp:
    for topic in ("dda-2d", "dda-3d"):
        for level in ("easy", "hard"):
            path = f"{tmp}/{topic}-{level}.json"
            subprocess.run([CLI, "practice", "make", topic, "--seed", "5", "--level", level,
                            "-o", path], check=True, capture_output=True)
            subprocess.run([CLI, "lesson", "validate", path], check=True, capture_output=True)
            key = subprocess.run([CLI, "lesson", "key", path], check=True,
                                 capture_output=True).stdout
            with open(f"{tmp}/key.json", "wb") as f:
                f.write(key)
            grade = json.loads(subprocess.run([CLI, "lesson", "check", path, "--answers",
                                               f"{tmp}/key.json", "--json"], check=True,
                                              capture_output=True).stdout)
            if grade["score"] != grade["out_of"] or grade["out_of"] < 7:
                fail(path, f"its own key does not score full marks: {grade}")

for f in failures[:40]:
    print(f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)

#!/usr/bin/env python3
"""raystep-cli assess checked by an independent reader: the exact DDA walk in Python fractions
(no raystep code), students' traces made from it with known slips, and the verdicts read back
with Python's json and csv modules.

    assess_test.py RAYSTEP_CLI [SEEDS]
"""
import csv
import json
import math
import os
import random
import subprocess
import sys
import tempfile
from fractions import Fraction as F

CLI = sys.argv[1]
SEEDS = int(sys.argv[2]) if len(sys.argv) > 2 else 300
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


def run(args, stdin=None):
    p = subprocess.run([CLI] + args, capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


# ---- the exact walk, in fractions --------------------------------------------------------


def boundary(lo, hi, res, k):
    return F(lo) + k * (F(hi) - F(lo)) / res


def exact_walk(res, lo, hi, o, d):
    """Cells of the walk from t = 0, ties stepping every tied axis, as docs/assignment-format.md
    says; each cell with its tMax (None: parallel). All in exact rationals of the doubles."""
    n = len(res)
    o = [F(x) for x in o]
    d = [F(x) for x in d]
    t_enter, t_exit = F(0), None
    for a in range(n):
        if d[a] == 0:
            if o[a] < F(lo[a]) or o[a] > F(hi[a]):
                return []
            continue
        t0 = (F(lo[a]) - o[a]) / d[a]
        t1 = (F(hi[a]) - o[a]) / d[a]
        t0, t1 = min(t0, t1), max(t0, t1)
        t_enter = max(t_enter, t0)
        t_exit = t1 if t_exit is None else min(t_exit, t1)
    if t_exit is not None and t_enter >= t_exit:
        return []
    cell = []
    for a in range(n):
        p = o[a] + t_enter * d[a]
        size = (F(hi[a]) - F(lo[a])) / res[a]
        k = math.floor((p - F(lo[a])) / size)
        if d[a] < 0 and p == boundary(lo[a], hi[a], res[a], k):
            k -= 1  # on a boundary moving down: the cell below it
        cell.append(min(max(k, 0), res[a] - 1))

    def tmax(a):
        if d[a] == 0:
            return None
        k = cell[a] + 1 if d[a] > 0 else cell[a]
        return (boundary(lo[a], hi[a], res[a], k) - o[a]) / d[a]

    cells = []
    while True:
        tm = [tmax(a) for a in range(n)]
        cells.append((tuple(cell), tm))
        finite = [t for t in tm if t is not None]
        if not finite:
            break
        m = min(finite)
        if t_exit is not None and m >= t_exit:
            break
        out = False
        for a in range(n):
            if tm[a] == m:
                cell[a] += 1 if d[a] > 0 else -1
                out = out or not (0 <= cell[a] < res[a])
        if out:
            break
    return cells


# ---- slips, written as a student would (floats, the slides' loop) -------------------------


def buggy_walk(res, lo, hi, o, d, bug):
    """The slides' loop with one bug: 'negative-direction-boundary' or 'no-entry-clip'."""
    n = len(res)
    t_enter, t_exit = 0.0, math.inf
    for a in range(n):
        if d[a] == 0:
            continue
        t0, t1 = (lo[a] - o[a]) / d[a], (hi[a] - o[a]) / d[a]
        t_enter, t_exit = max(t_enter, min(t0, t1)), min(t_exit, max(t0, t1))
    X, step, tMax, tDelta = [], [], [], []
    for a in range(n):
        size = (hi[a] - lo[a]) / res[a]
        p = o[a] if bug == "no-entry-clip" else o[a] + t_enter * d[a]
        X.append(int(min(max(math.floor((p - lo[a]) / size), 0), res[a] - 1)))
        step.append(1 if d[a] > 0 else (-1 if d[a] < 0 else 0))
        k = X[a] + 1 if (step[a] > 0 or bug == "negative-direction-boundary") else X[a]
        tMax.append((lo[a] + k * size - o[a]) / d[a] if step[a] else math.inf)
        tDelta.append(size / abs(d[a]) if step[a] else math.inf)
    cells = []
    while len(cells) < 200:
        cells.append(tuple(X))
        a = min(range(n), key=lambda i: tMax[i])
        if math.isinf(tMax[a]):
            break
        X[a] += step[a]
        if not 0 <= X[a] < res[a]:
            break
        tMax[a] += tDelta[a]
    return cells


# ---- traces -------------------------------------------------------------------------------


def ray_line(o, d):
    return json.dumps({"ray": {"origin": o, "dir": d}})


def cell_line(c, tm=None):
    rec = {"cell": list(c)}
    if tm is not None:
        rec["tMax"] = [None if t is None else float(t) for t in tm]
    return json.dumps(rec)


def grid_args(res, lo, hi):
    j = lambda v: ",".join(repr(float(x)) for x in v)
    return ["--grid", ",".join(map(str, res)), "--min", j(lo), "--max", j(hi)]


def random_case(rng):
    n = rng.choice([2, 3])
    res = [rng.randint(1, 7) for _ in range(n)]
    lo = [rng.choice([0.0, -1.5, 2.25, -3.0]) for _ in range(n)]
    size = [rng.choice([1.0, 0.5, 1.25, 0.75]) for _ in range(n)]
    hi = [lo[a] + size[a] * res[a] for a in range(n)]
    kind = rng.random()
    if kind < 0.2:
        # Through grid vertices: an exact tie (cells of equal size, a diagonal direction).
        s = size[0]
        size = [s] * n
        hi = [lo[a] + s * res[a] for a in range(n)]
        o = [lo[a] + s * 0.5 for a in range(n)]
        d = [rng.choice([1.0, 2.0])] * n
    else:
        inside = rng.random() < 0.6
        o = [
            rng.uniform(lo[a], hi[a]) if inside else rng.uniform(lo[a] - 3, hi[a] + 3)
            for a in range(n)
        ]
        o = [round(x, 3) for x in o]
        d = [round(rng.uniform(-1, 1), 3) for _ in range(n)]
        if rng.random() < 0.15:
            d[rng.randrange(n)] = rng.choice([0.0, -0.0])
        if all(x == 0 for x in d):
            d[0] = 0.5
    return n, res, lo, hi, o, d


def assess_dda(res, lo, hi, lines, extra=()):
    with tempfile.NamedTemporaryFile("w", suffix=".jsonl", delete=False) as f:
        f.write("\n".join(lines) + "\n")
        path = f.name
    try:
        code, out, err = run(["assess", "dda"] + grid_args(res, lo, hi) + ["--trace", path, "--json"] + list(extra))
    finally:
        os.unlink(path)
    return code, out, err


def main():
    rng = random.Random(31)
    checked = 0
    named = {}
    for seed in range(SEEDS):
        n, res, lo, hi, o, d = random_case(rng)
        walk = exact_walk(res, lo, hi, o, d)
        if not walk:
            continue
        where = f"seed {seed}: grid {res} {lo}..{hi}, ray {o} + t {d}"
        right = [ray_line(o, d)] + [cell_line(c, tm if seed % 2 else None) for c, tm in walk]
        # The slips, each with the index of the first differing record, found here.
        cells = [c for c, _ in walk]
        slips = []
        k = rng.randrange(len(cells))
        if len(cells) > 1:
            slips.append(("drop", cells[:k] + cells[k + 1:], k, "end" if k == len(cells) - 1 else "cell"))
        slips.append(("truncate", cells[:k], k, "end"))
        beyond = list(cells[-1])
        beyond[0] += 1
        slips.append(("extra", cells + [tuple(beyond)], len(cells), "cell"))
        wrong = list(cells[k])
        wrong[rng.randrange(n)] += rng.choice([-1, 1])
        slips.append(("swap", cells[:k] + [tuple(wrong)] + cells[k + 1:], k, "cell"))
        lines_by = {"right": (right, None, None)}
        for name, c, idx, rec in slips:
            lines_by[name] = ([ray_line(o, d)] + [cell_line(x) for x in c], idx, rec)
        if walk[k][1] and any(t is not None for t in walk[k][1]):
            tm = list(walk[k][1])
            a = next(i for i, t in enumerate(tm) if t is not None)
            tm[a] = tm[a] + F(1, 2)
            lines_by["tmax"] = ([ray_line(o, d)] + [cell_line(c, tm if i == k else None) for i, c in enumerate(cells)], k, "tMax")
        # One file, one ray each: the verdicts come back in order.
        names = list(lines_by)
        all_lines = []
        for nm in names:
            all_lines += lines_by[nm][0]
        code, out, err = assess_dda(res, lo, hi, all_lines)
        if code not in (0, 1):
            failures.append(f"{where}: exit {code}: {err.strip()}")
            continue
        v = json.loads(out)
        check(v["rays_total"] == len(names), f"{where}: {v['rays_total']} rays")
        for i, nm in enumerate(names):
            r = v["rays"][i]
            _, idx, rec = lines_by[nm]
            if nm == "right":
                check(r["passed"], f"{where}: the exact walk failed: {r['first_divergence']}")
                continue
            check(not r["passed"], f"{where}: slip {nm} passed")
            fd = r["first_divergence"] or {}
            check(fd.get("index") == idx, f"{where}: slip {nm}: index {fd.get('index')}, expected {idx}")
            check(fd.get("record") == rec, f"{where}: slip {nm}: record {fd.get('record')}, expected {rec}")
            check(bool(fd.get("explanation")), f"{where}: slip {nm}: no explanation")
            checked += 1
        check(code == 1, f"{where}: exit {code} with failed rays")
        # A known mistake, written here as a student would: its name must come back.
        for bug in ("negative-direction-boundary", "no-entry-clip"):
            bw = buggy_walk(res, lo, hi, o, d, bug)
            first = next((i for i in range(min(len(bw), len(cells))) if bw[i] != cells[i]), None)
            if first is None or bw == cells:
                continue
            code, out, err = assess_dda(res, lo, hi, [ray_line(o, d)] + [cell_line(c) for c in bw])
            r = json.loads(out)["rays"][0]
            check(r["first_divergence"]["index"] == first, f"{where}: {bug}: index {r['first_divergence']['index']}, expected {first}")
            got = (r["mistake"] or {}).get("name")
            # The slides' loop written here steps one axis at a tie: there, tie-one-axis explains
            # the cells as well.
            tie = len(set(d)) == 1
            check(got == bug or (tie and got == "tie-one-axis"), f"{where}: {bug}: named {got}")
            named[bug] = named.get(bug, 0) + (got == bug)
        # Skipping the start cell, a named mistake.
        if len(cells) > 1:
            code, out, err = assess_dda(res, lo, hi, [ray_line(o, d)] + [cell_line(c) for c in cells[1:]])
            r = json.loads(out)["rays"][0]
            check(r["first_divergence"]["index"] == 0, f"{where}: start skipped: index")
            named["start-cell-skipped"] = named.get("start-cell-skipped", 0) + (((r["mistake"] or {}).get("name")) == "start-cell-skipped")
    check(checked > SEEDS, f"only {checked} slips checked")
    for bug in ("start-cell-skipped", "negative-direction-boundary"):
        check(named.get(bug, 0) > 0, f"{bug} never named")
    print(f"{checked} slips checked; mistakes named: {named}")

    bad_input()
    tie_and_parallel()
    class_folder()
    if failures:
        print(f"{len(failures)} failures:")
        for f in failures[:40]:
            print("  " + f)
        sys.exit(1)
    print("all good")


def tie_and_parallel():
    """By hand: the tie through (1, 1) and a ray parallel to X, with the named mistakes."""
    g = ([4, 4], [0.0, 0.0], [4.0, 4.0])
    ray = ray_line([0.5, 0.5], [1.0, 1.0])
    code, out, _ = assess_dda(*g, [ray] + [cell_line(c) for c in [(0, 0), (1, 1), (2, 2), (3, 3)]])
    check(code == 0, f"diagonal walk: exit {code}: {out}")
    # The slides' loop: steps Y at the tie and visits (0, 1), a cell the ray only touches.
    code, out, _ = assess_dda(*g, [ray] + [cell_line(c) for c in [(0, 0), (0, 1), (1, 1), (1, 2)]])
    r = json.loads(out)["rays"][0]
    check(r["first_divergence"]["index"] == 1 and r["first_divergence"]["quantity"] == "tMaxX = tMaxY",
          f"tie: {r['first_divergence']}")
    check((r["mistake"] or {}).get("name") == "tie-one-axis", f"tie: mistake {r['mistake']}")
    # Parallel to X (dy = 0) with +0.0: step = -1 and -inf tMaxY walk down in Y.
    ray = ray_line([0.5, 2.5], [1.0, 0.0])
    code, out, _ = assess_dda(*g, [ray] + [cell_line(c) for c in [(0, 2), (0, 1), (0, 0)]])
    r = json.loads(out)["rays"][0]
    check(r["first_divergence"]["index"] == 1 and r["first_divergence"]["quantity"] == "tMaxY",
          f"parallel: {r['first_divergence']}")
    check((r["mistake"] or {}).get("name") == "parallel-axis-division", f"parallel: {r['mistake']}")
    # -0.0 taken for positive: (b - o) / -0.0 = -inf walks up in Y.
    ray = ray_line([0.5, 2.5], [1.0, -0.0])
    code, out, _ = assess_dda(*g, [ray] + [cell_line(c) for c in [(0, 2), (0, 3)]])
    r = json.loads(out)["rays"][0]
    check((r["mistake"] or {}).get("name") == "negative-zero", f"-0.0: {r['mistake']}")
    # From (-1, 0.5) along (1, 1): enters at t = 1, at (0, 1.5), so the walk starts in (0, 1);
    # the origin's row, clamped, is (0, 0).
    code, out, _ = assess_dda(*g, [ray_line([-1.0, 0.5], [1.0, 1.0])] + [cell_line(c) for c in [(0, 0), (0, 1), (1, 1)]])
    r = json.loads(out)["rays"][0]
    check(r["first_divergence"]["index"] == 0 and r["first_divergence"]["quantity"] == "tEnter",
          f"entry: {r['first_divergence']}")
    check((r["mistake"] or {}).get("name") == "no-entry-clip", f"entry: {r['mistake']}")
    # Italian: a decimal comma and the same index.
    code, out, _ = assess_dda(*g, [ray_line([0.5, 0.25], [1.0, 0.5])] + [cell_line(c) for c in [(0, 0), (0, 1)]], ["--lang", "it"])
    r = json.loads(out)["rays"][0]
    check("tMaxX = 0,5" in r["first_divergence"]["explanation"] and "Nella cella (0; 0)" in r["first_divergence"]["explanation"],
          f"Italian: {r['first_divergence']['explanation']}")


def bad_input():
    """One line naming the file and the line, exit 2, for each kind of bad trace."""
    g = grid_args([4, 4], [0.0, 0.0], [4.0, 4.0])
    cases = [
        ('{"ray": {"origin": [0.5, 0.5], "dir": [1, 0]}}\n{"cell": [0, 0]\n', ":2:", "not a JSON object"),
        ('{"ray": {"origin": [0.5, 0.5], "dir": [1, 0]}}\n{"cell": [0, 0], "tMax": [1, Infinity]}\n', ":2:", "Infinity"),
        ('{"cell": [0, 0]}\n', ":1:", "before the first"),
        ('{"ray": {"origin": [0.5, 0.5], "dir": [1, 0]}}\n{"cel": [0, 0]}\n', ":2:", "unknown record"),
        ('{"ray": {"origin": [0.5, 0.5, 1], "dir": [1, 0]}}\n', ":1:", "ray.origin"),
        ('{"ray": {"origin": [0.5, 0.5], "dir": [0, 0]}}\n', ":1:", "zero"),
        ('{"ray": {"origin": [0.5, 0.5], "dir": [1, 0]}}\n{"cell": [0.5, 0]}\n', ":2:", "whole number"),
        ('{"ray": {"origin": [0.5, 0.5], "dir": [1, 0]}}\n{"miss": true}\n{"cell": [0, 0]}\n', ":3:", "after this ray"),
        ("\n\n", "", "no ray"),
        ('{"ray": {"origin": [5.51e308, 0], "dir": [1, 0]}}\n', ":1:", "too large"),
    ]
    for text, line, words in cases:
        with tempfile.NamedTemporaryFile("w", suffix=".jsonl", delete=False) as f:
            f.write(text)
            path = f.name
        code, out, err = run(["assess", "dda"] + g + ["--trace", path])
        os.unlink(path)
        check(code == 2, f"bad input {text!r}: exit {code}")
        check(err.count("\n") == 1 and path + line in err and words in err, f"bad input {text!r}: {err!r}")
        check(out == "", f"bad input {text!r}: printed {out!r}")
    for args, words in [
        (["assess", "dda", "--trace", "/nonexistent.jsonl"] + g, "no such file"),
        (["assess", "dda", "--trace", "/tmp"] + g, "folder"),
        (["assess", "dda", "--grid", "4,0", "--min", "0,0", "--max", "4,4", "--trace", "/dev/null"], "--grid"),
        (["assess", "dda", "--grid", "4,4", "--min", "0,0", "--max", "4,nan", "--trace", "/dev/null"], "--max"),
        (["assess", "dda"] + g, "--trace"),
        (["assess", "nosuchscene", "--trace", "/dev/null"], "nosuchscene"),
    ]:
        code, out, err = run(args)
        check(code == 2 and words in err and err.count("\n") == 1, f"{args}: exit {code}, {err!r}")


def class_folder():
    """200 students: grades.csv read back with Python's csv, the grade recomputed here."""
    res, lo, hi = [6, 4], [0.0, 0.0], [6.0, 4.0]
    rays = [([0.4, 0.4], [0.8, 0.4]), ([5.5, 3.5], [-0.8, -0.5]), ([-1.0, 1.5], [1.0, 0.2])]
    walks = [[c for c, _ in exact_walk(res, lo, hi, o, d)] for o, d in rays]
    rng = random.Random(7)
    expected = {}
    skipped_students = 0
    with tempfile.TemporaryDirectory() as tmp:
        cls = os.path.join(tmp, "class")
        os.mkdir(cls)
        for s in range(200):
            sid = f"s{s:03d}"
            lines, passed, skips = [], 0, False
            for (o, d), w in zip(rays, walks):
                lines.append(ray_line(o, d))
                slip = rng.random()
                if slip < 0.5:
                    cells, ok = w, True
                elif slip < 0.75:
                    cells, ok, skips = w[1:], False, True
                else:
                    cells, ok = w[:-1], False
                lines += [cell_line(c) for c in cells]
                passed += ok
            skipped_students += skips
            if s % 2:
                os.mkdir(os.path.join(cls, sid))
                path = os.path.join(cls, sid, "walk.jsonl")
            else:
                path = os.path.join(cls, sid + ".jsonl")
            with open(path, "w") as f:
                f.write("\n".join(lines) + "\n")
            expected[sid] = 100.0 * passed / len(rays)
        with open(os.path.join(cls, "broken.jsonl"), "w") as f:
            f.write('{"ray": oops}\n')
        expected["broken"] = 0.0
        out_dir = os.path.join(tmp, "out")
        code, out, err = run(["assess", "dda"] + grid_args(res, lo, hi) + ["--class", cls, "-o", out_dir])
        check(code == 0, f"class: exit {code}: {err}")
        with open(os.path.join(out_dir, "grades.csv"), newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
        check([r["id"] for r in rows] == sorted(expected), "class: ids")
        for r in rows:
            check(abs(float(r["grade"]) - expected[r["id"]]) < 0.006, f"class: {r['id']} grade {r['grade']}, expected {expected[r['id']]:.2f}")
        broken = next(r for r in rows if r["id"] == "broken")
        check("unreadable" in broken["feedback"] and ":1:" in broken["feedback"], f"class: broken: {broken['feedback']}")
        md = open(os.path.join(out_dir, "class.md"), encoding="utf-8").read()
        check(f"| start-cell-skipped | {skipped_students} |" in md, f"class.md: start-cell-skipped {skipped_students}: {md}")
        check("Students: 201. Passed every ray: " in md and "Traces that could not be read: 1." in md, "class.md: count")


main()

#!/usr/bin/env python3
"""Independent check of the built-in lessons' spot_bug exercises (docs/lesson-format.md).

For each one, in exact fractions and with no raystep code: the exact walk of its ray on the
lesson's grid (Amanatides & Woo, every tied axis at once), the slides' loop with the exercise's
mistake made in it (as docs/assignment-format.md describes each), and the first step whose cell
differs, which must be the answer `raystep-cli lesson key` gives. Then every number its prompt
and hints write, in both languages, must be one this check computed (the ray, the grid, a cell,
a step, a tMax or tDelta of either walk, t_enter and the entry point), rounded as written; and
the claims the lesson 6 hint makes in words are checked one by one.

usage: spot_bug_lessons_test.py RAYSTEP_CLI SOURCE_DIR
"""
import json
import math
import re
import subprocess
import sys
from fractions import Fraction as F
from pathlib import Path

CLI, SOURCE = sys.argv[1], Path(sys.argv[2])
failures = []

# The lessons' grids, as their texts state them: lecture-grid's 6 x 4 cells of 1 x 1 from
# (0, 0); lecture-dda3d's box [-2, 2] x [0, 2] x [-2, 2] in 4 x 2 x 4 voxels of 1 x 1 x 1.
GRIDS = {
    "lecture-grid": ([F(0), F(0)], [F(6), F(4)], [6, 4]),
    "lecture-dda3d": ([F(-2), F(0), F(-2)], [F(2), F(2), F(2)], [4, 2, 4]),
}


def fail(where, message):
    failures.append(f"{where}: {message}")


def slab(lo, hi, o, d):
    t_enter, t_exit = F(0), None
    for a in range(len(lo)):
        if d[a] == 0:
            if o[a] < lo[a] or o[a] > hi[a]:
                return None
            continue
        t0, t1 = sorted(((lo[a] - o[a]) / d[a], (hi[a] - o[a]) / d[a]))
        t_enter = max(t_enter, t0)
        t_exit = t1 if t_exit is None else min(t_exit, t1)
    return (t_enter, t_exit) if t_exit is None or t_enter < t_exit else None


def exact_walk(lo, hi, res, o, d):
    """Cells with their tMax: the first cell just after the entry, then the nearest boundary."""
    n = len(lo)
    size = [(hi[a] - lo[a]) / res[a] for a in range(n)]
    t_enter, t_exit = slab(lo, hi, o, d)

    def cross(a, k):
        return (lo[a] + k * size[a] - o[a]) / d[a]

    cell = []
    for a in range(n):
        if d[a] > 0:
            cell.append(max(k for k in range(res[a]) if cross(a, k) <= t_enter))
        else:
            cell.append(max(k for k in range(res[a]) if cross(a, k) > t_enter))

    def t_max():
        return [cross(a, cell[a] + (1 if d[a] > 0 else 0)) for a in range(n)]

    walk = [(tuple(cell), t_max())]
    while True:
        tm = t_max()
        m = min(tm)
        if t_exit is not None and m >= t_exit:
            break
        for a in range(n):
            if tm[a] == m:
                cell[a] += 1 if d[a] > 0 else -1
        if any(c < 0 or c >= r for c, r in zip(cell, res)):
            break
        walk.append((tuple(cell), t_max()))
    return walk, t_enter, size


def slides_walk(lo, hi, res, o, d, mistake):
    """The slides' loop (tMax += tDelta) with one of the mistakes these lessons use."""
    n = len(lo)
    size = [(hi[a] - lo[a]) / res[a] for a in range(n)]
    t_enter, _ = slab(lo, hi, o, d)
    cell, step, t_max, t_delta = [], [], [], []
    for a in range(n):
        # no-entry-clip: the origin's cell, clamped into the grid, not the entry point's.
        p = o[a] if mistake == "no-entry-clip" else o[a] + t_enter * d[a]
        # The cell the ray goes into: on a boundary moving down, the one below it.
        f = (p - lo[a]) / size[a]
        c = math.ceil(f) - 1 if d[a] < 0 and mistake != "no-entry-clip" else math.floor(f)
        cell.append(min(max(c, 0), res[a] - 1))
        step.append(1 if d[a] > 0 else -1)
        # negative-direction-boundary: the boundary X + 1 also when moving down.
        k = cell[a] + 1 if mistake == "negative-direction-boundary" or step[a] > 0 else cell[a]
        t_max.append((lo[a] + k * size[a] - o[a]) / d[a])
        t_delta.append(size[a] / abs(d[a]))
    walk = []
    while True:
        walk.append((tuple(cell), list(t_max)))
        m = min(t_max)
        out = False
        for a in range(n):
            if t_max[a] == m:
                cell[a] += step[a]
                t_max[a] += t_delta[a]
                out = out or cell[a] < 0 or cell[a] >= res[a]
        if out:
            return walk, t_delta


def numbers_in(text, italian):
    """The numbers a reader sees: in Italian prose a comma glued to digits is a decimal mark."""
    out = []
    parts = re.split(r"(`[^`]*`)", text)
    for part in parts:
        code = part.startswith("`")
        mark = r"[.,]" if italian and not code else r"\."
        for m in re.finditer(r"(?<![\w.])-?\d+(?:" + mark + r"\d+)?(?![\w])", part):
            out.append(m.group(0).replace(",", "."))
    return out


def accounted(written, values):
    w = F(written)
    decimals = len(written.split(".")[1]) if "." in written else 0
    half = F(1, 2) / 10**decimals
    return any(abs(w - v) <= half for v in values)


def main():
    lessons = {}
    for path in sorted((SOURCE / "lessons").glob("*.json")):
        text = "\n".join(l for l in path.read_text().splitlines() if not l.lstrip().startswith("//"))
        lessons[path.name] = json.loads(text)
    checked = 0
    for name, lesson in lessons.items():
        for ex in lesson.get("exercises", []):
            if ex["type"] != "spot_bug":
                continue
            where = f"{name} {ex['id']}"
            checked += 1
            lo, hi, res = GRIDS[lesson["scene"]]
            res = lesson.get("setup", {}).get("grid_res", res)
            if "ray" in ex:
                o = [F(repr(v)) for v in ex["ray"]["o"]]
                d = [F(repr(v)) for v in ex["ray"]["d"]]
            else:
                # The lesson's own ray, as the prompt states it.
                prompt = ex["prompt"]["en"]
                vec = r"\(([-\d., ]+)\)"
                o = [F(v) for v in re.search(r"`o = " + vec, prompt).group(1).split(",")]
                d = [F(v) for v in re.search(r"`d = " + vec, prompt).group(1).split(",")]
            exact, t_enter, size = exact_walk(lo, hi, res, o, d)
            wrong, t_delta = slides_walk(lo, hi, res, o, d, ex["mistake"])
            k = next((i for i in range(len(wrong))
                      if i >= len(exact) or wrong[i][0] != exact[i][0]), None)
            if k is None:
                fail(where, "the mistake never enters a wrong cell")
                continue
            key = json.loads(subprocess.run([CLI, "lesson", "key", str(lesson["number"])],
                                            capture_output=True, check=True).stdout)
            if key["answers"].get(ex["id"]) != str(k):
                fail(where, f"raystep's answer {key['answers'].get(ex['id'])}, recomputed {k}")
            # Every number written must be one of these.
            values = set(o) | set(d) | set(lo) | set(hi) | set(size) | {F(r) for r in res}
            values |= {t_enter} | {o[a] + t_enter * d[a] for a in range(len(o))}
            values |= set(t_delta) | {F(i) for i in range(max(len(exact), len(wrong)))}
            for cell, t_max in exact + wrong:
                values |= {F(c) for c in cell} | set(t_max)
            texts = [ex["prompt"]] + ex.get("hint", [])
            for t in texts:
                for lang, text in t.items():
                    for written in numbers_in(text, lang == "it"):
                        if not accounted(written, values):
                            fail(where, f"{lang}: {written} is none of the numbers recomputed")
            if lesson["number"] == 6:
                # The hint's claims: the start cell (5, 0), going left, the line ahead x = 5
                # crossed at (5 - 5.3) / (-0.9) = 0.333, and tMaxY = 2 there.
                if exact[0][0] != (5, 0) or d[0] >= 0:
                    fail(where, f"the walk starts in {exact[0][0]}, d = {d}")
                if (F(5) - o[0]) / d[0] != exact[0][1][0] or round(float(exact[0][1][0]), 3) != 0.333:
                    fail(where, f"tMaxX at step 0 is {exact[0][1][0]}")
                if exact[0][1][1] != 2:
                    fail(where, f"tMaxY at step 0 is {exact[0][1][1]}")
                if wrong[0][1][0] == exact[0][1][0]:
                    fail(where, "the replayed walk's tMaxX at step 0 is the exact one")
    if checked < 2:
        fail("lessons", f"only {checked} spot_bug exercises found (lessons 6 and 7 have one)")
    for f in failures:
        print("FAIL", f)
    print(f"{checked} spot_bug exercises checked, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

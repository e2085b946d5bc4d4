#!/usr/bin/env python3
"""Independent check of the mailbox, phong and ray-tree practice topics (docs/practice.md).

mailbox: every count of `raystep-cli practice make mailbox --seed S --level L --json` is
recomputed from its `given` alone, in exact fractions and with no raystep code: the cells each
primitive's bounding box overlaps, a DDA walk written from Amanatides & Woo's paper that stops
after the cell whose far side lies beyond the nearest hit found so far, the tests without a
mailbox (every listed primitive in every cell of the walk), with one (each primitive once) and
the skips. phong: n.l, r.v, the diffuse and specular terms from the slides' formulas in exact
fractions, with phong()'s convention (no term at all with the light behind the surface).
ray-tree: a Whitted tree on the camera's axis traced here in one dimension from raystep's rules
(a shadow ray per light on the side the ray came from, at every hit; reflection and refraction
rays below `bounces`), counted by kind and by depth.
Each level's rules are checked, the same seed gives the same bytes, instances rarely repeat,
and a lesson file written with -o validates and its own key scores full marks in both
languages.

usage: mailbox_phong_test.py RAYSTEP_CLI [SEEDS [TOPICS]]
"""
import sys
from fractions import Fraction as F

import practice_sweep

CLI = sys.argv[1]
SEEDS = int(sys.argv[2]) if len(sys.argv) > 2 else 200
TOPICS = sys.argv[3].split(",") if len(sys.argv) > 3 else ("mailbox", "phong", "ray-tree")
failures = []


def fail(where, message):
    # `where` is the sweep's fail for this instance, or a place named in text.
    if callable(where):
        where(message)
    else:
        failures.append(f"{where}: {message}")


def exact(x):
    # The JSON number as written: the decimal the student reads.
    return F(repr(x)) if isinstance(x, float) else F(x)


def cross(p, q):
    return p[0] * q[1] - p[1] * q[0]


def dot(p, q):
    return sum(x * y for x, y in zip(p, q))


# --- mailbox -------------------------------------------------------------------------------

def floor_div(x, cell):
    q = x / cell
    return q.numerator // q.denominator


def walk(lo, cell, res, o, d):
    """The DDA from the ray's first point in the grid: [(cell, t_exit, gap)], gap the least
    distance between the two axes' next crossings there (0: a tie)."""
    t_enter, t_exit = F(0), None
    for a in range(2):
        hi = lo[a] + cell * res[a]
        if d[a] == 0:
            if not lo[a] < o[a] < hi:
                return []
            continue
        t0, t1 = (lo[a] - o[a]) / d[a], (hi - o[a]) / d[a]
        t0, t1 = min(t0, t1), max(t0, t1)
        t_enter = max(t_enter, t0)
        t_exit = t1 if t_exit is None else min(t_exit, t1)
    if t_exit is None or t_enter >= t_exit:
        return []
    p = [o[a] + t_enter * d[a] for a in range(2)]
    c = [min(max(floor_div(p[a] - lo[a], cell), 0), res[a] - 1) for a in range(2)]
    t_max = []
    for a in range(2):
        if d[a] == 0:
            t_max.append(None)
            continue
        bound = lo[a] + cell * (c[a] + (1 if d[a] > 0 else 0))
        t_max.append((bound - o[a]) / d[a])
    out = []
    while True:
        ahead = [t for t in t_max if t is not None]
        nearest = min(ahead)
        gap = abs(ahead[0] - ahead[1]) if len(ahead) == 2 else None
        exit_t = min(nearest, t_exit)
        out.append((tuple(c), exit_t, gap, t_enter if not out else None))
        if nearest >= t_exit:
            return out
        for a in range(2):
            if t_max[a] == nearest:
                c[a] += 1 if d[a] > 0 else -1
                t_max[a] += cell / abs(d[a])
        if not all(0 <= c[a] < res[a] for a in range(2)):
            return out


def meet(prim, o, d, cell):
    """(hit t or None, clear): whether a drawing by hand decides it, 0.1 of a cell apart."""
    m = cell / 10
    if prim["type"] == "circle":
        c, r = [exact(x) for x in prim["center"]], exact(prim["radius"])
        f = [c[a] - o[a] for a in range(2)]
        dist2 = dot(f, f) - dot(f, d) ** 2 / dot(d, d)
        return None, dist2 >= (r + m) ** 2
    a, b = [exact(x) for x in prim["from"]], [exact(x) for x in prim["to"]]
    e = [b[k] - a[k] for k in range(2)]
    ao = [a[k] - o[k] for k in range(2)]
    den = cross(d, e)
    if den == 0:
        dist2 = cross(ao, d) ** 2 / dot(d, d)
        return None, dist2 >= m * m
    t, u = cross(ao, e) / den, cross(ao, d) / den
    len2, speed2 = dot(e, e), dot(d, d)
    if 0 <= u <= 1 and t > 0:
        return t, (u * u * len2 >= m * m and (1 - u) ** 2 * len2 >= m * m
                   and t * t * speed2 >= m * m)
    off = (u < 0 and u * u * len2 >= m * m) or (u > 1 and (u - 1) ** 2 * len2 >= m * m)
    return None, off or (t < 0 and t * t * speed2 >= m * m)


def check_mailbox(j, level, where):
    g, ans = j["given"], j["answers"]
    res = g["grid"]
    lo, hi = [exact(x) for x in g["min"]], [exact(x) for x in g["max"]]
    o, d = [exact(x) for x in g["origin"]], [exact(x) for x in g["dir"]]
    cell = (hi[0] - lo[0]) / res[0]
    if (hi[1] - lo[1]) / res[1] != cell or cell not in (F(1, 2), F(1), F(2)):
        fail(where, f"cells of {cell}, or not square")
    prims = g["primitives"]
    ids = [p["id"] for p in prims]
    if ids != list(range(2, 2 + len(prims))):
        fail(where, f"primitive ids {ids} are not 2, 3, ... (the markers are 0 and 1)")
    kinds = [p["type"] for p in prims]
    if kinds != sorted(kinds):  # raystep's ids: circles first, then segments
        fail(where, f"circles do not come before segments: {kinds}")
    listed = []
    for p in prims:
        if p["type"] == "circle":
            c, r = [exact(x) for x in p["center"]], exact(p["radius"])
            if r <= 0:
                fail(where, "a circle of radius <= 0")
            box = [(c[a] - r, c[a] + r) for a in range(2)]
            pts = [c]
        else:
            a, b = [exact(x) for x in p["from"]], [exact(x) for x in p["to"]]
            box = [(min(a[k], b[k]), max(a[k], b[k])) for k in range(2)]
            pts = [a, b]
        for pt in pts:
            for x, base in zip(pt, lo):
                if ((x - base) / cell * 10).denominator != 1:
                    fail(where, f"a coordinate {x} not in tenths of a cell")
        cells = set()
        rng = []
        for k in range(2):
            e0, e1 = [(x - lo[k]) / cell for x in box[k]]
            for e in (e0, e1):
                if e.denominator == 1 or e <= 0 or e >= res[k]:
                    fail(where, f"primitive {p['id']}'s bounding box on a grid line or outside")
            rng.append(range(floor_div(box[k][0] - lo[k], cell),
                             floor_div(box[k][1] - lo[k], cell) + 1))
        for y in rng[1]:
            for x in rng[0]:
                cells.add((x, y))
        if cells != {tuple(c) for c in p["cells"]} or len(p["cells"]) != len(cells):
            fail(where, f"primitive {p['id']}: cells {p['cells']}, expected {sorted(cells)}")
        listed.append(cells)
    if len({frozenset(c) for c in listed}) != len(listed):
        fail(where, "two primitives over the same cells")
    full = walk(lo, cell, res, o, d)
    if not full:
        fail(where, "the ray misses the grid")
        return None
    for k, (c, _, gap, t_in) in enumerate(full):
        if gap is not None and gap < F(1, 20):
            fail(where, f"a near tie at cell {c}: the tMax differ by {gap}")
    if full[0][1] - (full[0][3] or 0) < F(1, 20):
        fail(where, "the walk starts next to a boundary")
    hits = {}
    for p in prims:
        t, clear = meet(p, o, d, cell)
        if not clear:
            fail(where, f"primitive {p['id']}: too close to call by hand")
        if t is not None:
            hits[p["id"]] = t
    # The walk with the grid's early exit: after a cell, stop if the nearest hit among the
    # primitives tested so far lies before the cell's far side.
    without = with_box = skips = 0
    seen, nearest, walked, first_cell = set(), None, [], {}
    for k, (c, exit_t, _, _) in enumerate(full):
        walked.append(c)
        for p, cells in zip(prims, listed):
            if c not in cells:
                continue
            without += 1
            if p["id"] in seen:
                skips += 1
            else:
                seen.add(p["id"])
                with_box += 1
                first_cell[p["id"]] = k
                if p["id"] in hits and (nearest is None or hits[p["id"]] < nearest[1]):
                    nearest = (p["id"], hits[p["id"]])
        if nearest is not None and nearest[1] < exit_t:
            break
    for key, want in (("testsWithout", without), ("testsWith", with_box), ("saved", skips)):
        if ans[key] != want:
            fail(where, f"{key} is {ans[key]}, expected {want}")
    if [tuple(c) for c in ans["walk"]] != walked:
        fail(where, f"walk {ans['walk']}, expected {walked}")
    if ans["hit"] != (nearest[0] if nearest else None):
        fail(where, f"hit {ans['hit']}, expected {nearest}")
    key = {e["id"]: e["answer"] for e in j["exercises"]}
    if key != {"tests-without": str(without), "tests-with": str(with_box), "saved": str(skips)}:
        fail(where, f"the exercises' answers {key}")
    corners = {(0, 0), (res[0] - 1, res[1] - 1)}
    if corners & set(walked):
        fail(where, "the walk passes a corner marker's cell")
    if not 3 <= len(walked) <= (6 if level == "easy" else 8):
        fail(where, f"a walk of {len(walked)} cells")
    stop = len(walked) - 1
    for t in hits.values():
        for c, exit_t, _, _ in full:
            if abs(t - exit_t) < F(1, 20):
                fail(where, f"a hit at t = {t} next to a cell's side")
    if level == "easy":
        if len(prims) != 1 or len(listed[0]) != 2 or not listed[0] <= set(walked) or nearest:
            fail(where, "easy: not one primitive over two cells of the walk, missed")
    elif level == "medium":
        if not 3 <= len(prims) <= 4 or nearest or skips < 2:
            fail(where, f"medium: {len(prims)} primitives, hit {nearest}, {skips} skips")
    else:
        if nearest is None or len(hits) != 1:
            fail(where, f"hard: hits {hits}")
            return "bad"
        target = nearest[0]
        if prims[target - 2]["type"] != "segment":
            fail(where, "hard: the hit primitive is not a segment")
        if first_cell[target] >= stop:
            fail(where, "hard: the hit primitive is first tested in the cell of its hit")
        if stop == len(full) - 1:
            fail(where, "hard: the walk does not stop before the grid's end")
        after = set(c for c, _, _, _ in full[stop + 1:])
        if not any(cells & after and not cells & set(walked) for cells in listed):
            fail(where, "hard: the early exit saves no test of a primitive of its own")
        if not 3 <= len(prims) <= 4:
            fail(where, f"hard: {len(prims)} primitives")
    return "outside" if o[0] < lo[0] or o[0] > hi[0] or o[1] < lo[1] or o[1] > hi[1] else "in"


# --- phong ---------------------------------------------------------------------------------

NICE = {F(0), F(6, 10), F(8, 10), F(1), F(36, 100), F(48, 100), F(64, 100)}


def check_phong(j, level, where):
    g, ans = j["given"], j["answers"]
    n, l = [exact(x) for x in g["n"]], [exact(x) for x in g["l"]]
    kd, light = exact(g["kd"]), exact(g["intensity"])
    for name, v in (("n", n), ("l", l)):
        if dot(v, v) != 1 or any(abs(x) not in NICE for x in v):
            fail(where, f"{name} = {v} is not a unit vector of hand-workable components")
    nl = dot(n, l)
    diffuse = kd * light * max(F(0), nl)
    for key, want in (("nDotL", nl), ("diffuse", diffuse)):
        if abs(F(ans[key]) - want) > F(1, 10 ** 9):
            fail(where, f"{key} is {ans[key]}, expected {float(want)}")
    if kd not in {F(k, 10) for k in range(1, 10)} or light not in (F(1, 2), F(1), F(2)):
        fail(where, f"kd {kd} or I {light} not a short decimal")
    asked = [e["id"] for e in j["exercises"]]
    if level == "easy":
        if "specular" in asked or ans["specular"] is not None or nl <= 0:
            fail(where, "easy: a specular term asked, or the light behind")
        if abs(nl) < F(1, 5):
            fail(where, f"easy: a grazing light, n.l = {nl}")
        return "diffuse"
    v = [exact(x) for x in g["v"]]
    ks, shininess = exact(g["ks"]), g["shininess"]
    if dot(v, v) != 1 or any(abs(x) not in NICE for x in v):
        fail(where, f"v = {v} is not a unit vector of hand-workable components")
    if dot(n, v) <= 0:
        fail(where, "the eye is behind the surface")
    if shininess not in range(1, 6) or ks not in {F(k, 10) for k in range(1, 10)}:
        fail(where, f"shininess {shininess} or ks {ks} not small")
    r = [2 * nl * n[k] - l[k] for k in range(3)]
    rv = dot(r, v)
    # phong(): the light behind the surface gives no highlight, whatever r.v.
    specular = ks * light * max(F(0), rv) ** shininess if nl > 0 else F(0)
    for key, want in (("rDotV", rv), ("specular", specular)):
        if ans.get(key) is None and key == "rDotV" and "r-dot-v" not in asked:
            continue
        if ans[key] is None or abs(F(ans[key]) - want) > F(1, 10 ** 9):
            fail(where, f"{key} is {ans[key]}, expected {float(want)}")
    if abs(nl) < F(1, 5) or abs(rv) < F(1, 5):
        fail(where, f"a grazing case: n.l = {nl}, r.v = {rv}")
    if level == "medium":
        if nl <= 0 or rv <= 0:
            fail(where, "medium: the light behind or r.v <= 0")
        if specular < F(1, 20):
            fail(where, f"medium: a specular term {float(specular)} below 0.05")
        return "both"
    if nl > 0 and rv > 0:
        fail(where, "hard: neither the light behind nor r.v < 0")
    return "behind" if nl < 0 else "away"


# --- ray-tree ------------------------------------------------------------------------------

def check_ray_tree(j, level, where):
    """Whitted's tree on the z axis, from raystep's rules as docs/practice.md states them: at
    every hit a shadow ray per light on the side the ray came from; below `bounces` a
    reflection ray (mirror, glass) and a refraction ray (glass); head-on, so reflections go
    straight back and refractions straight on."""
    g, ans = j["given"], j["answers"]
    if g["pixel"] != [16, 12] or g["image"] != [33, 25]:
        fail(where, "not the centre pixel of a 33 x 25 image")
    eye = [exact(x) for x in g["eye"]]
    if eye[0] or eye[1]:
        fail(where, "the eye is off the axis")
    balls = []
    for b in g["spheres"]:
        c = [exact(x) for x in b["center"]]
        if c[0] or c[1] or c[2].denominator != 1 or b["radius"] != int(b["radius"]):
            fail(where, f"a sphere off the axis or not in whole numbers: {b}")
        balls.append((c[2] - b["radius"], c[2] + b["radius"], b["material"]))
    balls.sort()
    for (lo1, hi1, _), (lo2, hi2, _) in zip(balls, balls[1:]):
        if hi1 >= lo2:
            fail(where, "two spheres touch")
    if any(hi >= eye[2] for _, hi, _ in balls):
        fail(where, "the eye inside or behind a sphere")
    lights = [[exact(x) for x in p] for p in g["lights"]]
    surfaces = [z for lo, hi, _ in balls for z in (lo, hi)]
    for p in lights:
        if p[0] == 0 and p[1] == 0:
            fail(where, "a light on the axis")
        if any(abs(p[2] - z) < F(1, 2) for z in surfaces):
            fail(where, f"a light level with a surface: {p}")
    bounces = g["bounces"]
    counts = {}

    def begin(kind, depth):
        counts[(kind, depth)] = counts.get((kind, depth), 0) + 1

    def trace(z, s, inside, depth, kind):
        # A ray from z along s (+1 or -1); inside: the index of the sphere it is in, or None.
        begin(kind, depth)
        if inside is not None:
            lo, hi, mat = balls[inside]
            hit, k = (hi if s > 0 else lo), inside
        else:
            ahead = [(lo if s > 0 else hi, i) for i, (lo, hi, _) in enumerate(balls)
                     if (lo > z if s > 0 else hi < z)]
            if not ahead:
                return
            hit, k = min(ahead) if s > 0 else max(ahead)
        mat = balls[k][2]
        for p in lights:
            if -s * (p[2] - hit) > 0:  # the normal faces the incoming ray: -s along z
                begin("shadow", depth + 1)
        if depth >= bounces:
            return
        if mat in ("mirror", "glass"):
            trace(hit, -s, inside, depth + 1, "reflection")
        if mat == "glass":
            trace(hit, s, None if inside is not None else k, depth + 1, "refraction")

    trace(eye[2], -1, None, 0, "primary")

    def total(kind=None, depth=None):
        return sum(n for (k, d), n in counts.items()
                   if (kind is None or k == kind) and (depth is None or d == depth))

    want = {"shadowRays": total("shadow"), "reflectionRays": total("reflection"),
            "refractionRays": total("refraction"),
            "raysAtDepth": {"depth": g["depth"], "count": total(depth=g["depth"])}}
    for key, value in want.items():
        if ans[key] != value:
            fail(where, f"{key} is {ans[key]}, expected {value}")
    rays = total()
    if not 3 <= rays <= 24 or want["raysAtDepth"]["count"] == 0:
        fail(where, f"{rays} rays, or none at depth {g['depth']}")
    mats = [m for _, _, m in balls]
    if level == "easy" and (bounces > 2 or len(lights) != 1):
        fail(where, "easy: more than 2 bounces or not one light")
    if level != "easy" and balls[-1][2] != "glass":
        fail(where, f"{level}: the sphere nearest the eye is not glass")
    if level == "hard" and ("mirror" not in mats or len(lights) != 2 or bounces < 3):
        fail(where, "hard: no mirror, not two lights, or fewer than 3 bounces")
    return f"{rays} rays"


# --- the runs ------------------------------------------------------------------------------

CHECKS = {"mailbox": check_mailbox, "phong": check_phong, "ray-tree": check_ray_tree}


def adapt(check):
    # The sweep's fail(message) knows where; the checks here take it as their `where`.
    return lambda j, level, fail_here: check(j, level, fail_here)


errors = []
kinds = practice_sweep.sweep(CLI, [(t, adapt(CHECKS[t])) for t in TOPICS], SEEDS, 5, errors)
if "phong" in TOPICS and len(kinds[("phong", "hard")]) < 2:
    errors.append("phong hard: only one case drawn: %s" % kinds[("phong", "hard")])
practice_sweep.lesson_files_score(CLI, TOPICS, errors)
errors += failures
sys.exit(practice_sweep.finish(errors))

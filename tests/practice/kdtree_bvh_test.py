#!/usr/bin/env python3
"""An independent check of the kdtree and bvh practice topics (no raystep code): P(L|C), P(R|C)
and the SAH cost recomputed in exact fractions from `given` (in 2D the perimeter ratio), N_L and
N_R counted again from the primitives, the cheapest of the three candidates, the nodes TestTree
enters (a kd-tree walk of this file's own, after lesson 10) and the boxes a BVH traversal enters
with its primitive tests (a slab test of its own); each level's rules; the same seed gives the
same bytes; most instances of a level differ; a `-o` file validates and its own key scores full
marks in both languages.

Usage: kdtree_bvh_test.py RAYSTEP_CLI [SEEDS]"""
import math
import sys
from fractions import Fraction as F

import practice_sweep

AXES = {"x": 0, "y": 1}


def close(got, want):
    return got is not None and abs(got - float(want)) <= 1e-9 * max(1.0, abs(float(want)))


def fr(v):
    return F(v).limit_denominator(1000)


def on_lattice(v, per_unit):
    return (F(v) * per_unit).denominator == 1


def prims_of(g):
    """[(kind, data, (lo, hi))] in the engine's ids: circles first, then segments."""
    out = []
    for c in g["circles"]:
        cx, cy, r = fr(c["center"][0]), fr(c["center"][1]), fr(c["radius"])
        out.append(("circle", (cx, cy, r), ((cx - r, cy - r), (cx + r, cy + r))))
    for s in g["segments"]:
        a = (fr(s["from"][0]), fr(s["from"][1]))
        b = (fr(s["to"][0]), fr(s["to"][1]))
        out.append(("segment", (a, b), ((min(a[0], b[0]), min(a[1], b[1])),
                                        (max(a[0], b[0]), max(a[1], b[1])))))
    return out


def hit(prim, o, d):
    """The t > 0 where the ray meets the primitive, or None (floats for a circle's root)."""
    kind, data, _ = prim
    if kind == "circle":
        cx, cy, r = data
        fx, fy = o[0] - cx, o[1] - cy
        a = d[0] ** 2 + d[1] ** 2
        b = 2 * (d[0] * fx + d[1] * fy)
        c = fx * fx + fy * fy - r * r
        disc = b * b - 4 * a * c
        if disc < 0:
            return None
        s = math.sqrt(disc)
        for t in ((-b - s) / (2 * a), (-b + s) / (2 * a)):
            if t > 0:
                return float(t)
        return None
    (ax, ay), (bx, by) = data
    ex, ey = bx - ax, by - ay
    den = d[0] * ey - d[1] * ex
    if den == 0:
        return None
    fx, fy = ax - o[0], ay - o[1]
    t = (fx * ey - fy * ex) / den
    u = (fx * d[1] - fy * d[0]) / den
    return t if t > 0 and 0 <= u <= 1 else None


def slab(o, d, lo, hi, tmin, tmax):
    tn, tf = tmin, tmax
    for i in (0, 1):
        t0, t1 = (lo[i] - o[i]) / d[i], (hi[i] - o[i]) / d[i]
        if t0 > t1:
            t0, t1 = t1, t0
        tn, tf = max(tn, t0), min(tf, t1)
        if tn > tf:
            return None
    return tn, tf


def perimeter(lo, hi):
    return 2 * ((hi[0] - lo[0]) + (hi[1] - lo[1]))


def sah(g, lo, hi, axis, at, nl, nr):
    """P(L|C), P(R|C) by perimeters (lesson 11) and the cost with the empty bonus."""
    left_hi = list(hi)
    left_hi[axis] = at
    right_lo = list(lo)
    right_lo[axis] = at
    pc = perimeter(lo, hi)
    pl, pr = perimeter(lo, left_hi) / pc, perimeter(right_lo, hi) / pc
    cost = fr(g["cTrav"]) + fr(g["cIsect"]) * (pl * nl + pr * nr)
    if nl == 0 or nr == 0:
        cost *= 1 - fr(g["emptyBonus"])
    return pl, pr, cost


def count_sides(prims, lo, hi, axis, at, fail):
    """N_L, N_R of the primitives whose bounds lie in the node; a primitive on the plane fails."""
    nl = nr = 0
    for _, _, (plo, phi) in prims:
        inside = all(plo[i] >= lo[i] and phi[i] <= hi[i] for i in (0, 1))
        if not inside:
            continue
        if plo[axis] == at or phi[axis] == at:
            fail("a primitive's bound lies on the plane %s" % at)
        nl += plo[axis] < at
        nr += phi[axis] > at
    return nl, nr


def test_tree(nodes, prims, o, d, root_lo, root_hi):
    """TestTree as lesson 10 states raystep's: near child first, the far one on a stack with its
    part of [tNear, tFar], stop when the nearest hit lies before the next node's tNear."""
    rng = slab(o, d, root_lo, root_hi, F(0), F(10 ** 9))
    if rng is None:
        return []
    tn, tf = rng
    stack, visits, tested, closest, nid = [], [], set(), None, 0
    while True:
        if closest is not None and closest < tn:
            break
        visits.append(nid)
        n = nodes[nid]
        if "children" in n:
            a, at = AXES[n["axis"]], fr(n["position"])
            left, right = n["children"]
            below = o[a] < at or (o[a] == at and d[a] <= 0)
            first, second = (left, right) if below else (right, left)
            ts = (at - o[a]) / d[a]
            if not ts > 0 or ts > tf:
                nid = first
            elif ts < tn:
                nid = second
            else:
                stack.append((second, max(ts, tn), tf))
                nid, tf = first, min(ts, tf)
            continue
        for p in n["prims"]:
            if p in tested:
                continue  # the mailbox
            tested.add(p)
            t = hit(prims[p], o, d)
            if t is not None and (closest is None or t < closest):
                closest = t
        if not stack:
            break
        nid, tn, tf = stack.pop()
    return visits


def check_kdtree(j, level, fail):
    g, a = j["given"], j["answers"]
    for key in ("min", "max", "axis", "position", "nl", "nr", "cTrav", "cIsect", "emptyBonus"):
        if key not in g:
            fail("given has no %s" % key)
            return None
    for key in ("pL", "pR", "cost"):
        if key not in a:
            fail("answers has no %s" % key)
            return None
    prims = prims_of(g)
    lo, hi = [fr(v) for v in g["min"]], [fr(v) for v in g["max"]]
    axis, at, nl, nr = AXES[g["axis"]], fr(g["position"]), g["nl"], g["nr"]
    for v in lo + hi + [at]:
        if not on_lattice(v, 2):
            fail("a corner or plane off the half-unit lattice: %s" % v)
    if not (isinstance(nl, int) and isinstance(nr, int) and 0 <= nl <= 6 and 0 <= nr <= 6):
        fail("N_L, N_R not small whole numbers: %r, %r" % (nl, nr))
    if not lo[axis] < at < hi[axis]:
        fail("the plane is not inside the node")
    if count_sides(prims, lo, hi, axis, at, fail) != (nl, nr):
        fail("N_L, N_R are %r, %r; the primitives give %r"
             % (nl, nr, count_sides(prims, lo, hi, axis, at, fail)))
    root_lo = [min(p[2][0][i] for p in prims) for i in (0, 1)]
    root_hi = [max(p[2][1][i] for p in prims) for i in (0, 1)]
    if [fr(v) for v in g["root"]["min"]] != root_lo or [fr(v) for v in g["root"]["max"]] != root_hi:
        fail("the root box is not the primitives' bounds")
    empty = nl == 0 or nr == 0
    if level == "hard":
        if not empty:
            fail("hard: the named plane leaves no side empty")
        if g["node"] == 0:
            fail("hard: the node is the root")
    else:
        if empty or g["node"] != 0 or lo != root_lo or hi != root_hi:
            fail("%s: not a plane of the root with both sides full" % level)
    pl, pr, cost = sah(g, lo, hi, axis, at, nl, nr)
    for key, want in (("pL", pl), ("pR", pr), ("cost", cost)):
        if not close(a[key], want):
            fail("%s is %r, expected %s = %r" % (key, a[key], want, float(want)))
    if level == "easy":
        if "visits" in a or "cheapest" in a:
            fail("easy asks more than the plane")
        return "easy"
    costs = []
    for c in g["candidates"]:
        ca, cat = AXES[c["axis"]], fr(c["position"])
        if not on_lattice(cat, 2) or not lo[ca] < cat < hi[ca]:
            fail("a candidate off the lattice or outside the node")
        if count_sides(prims, lo, hi, ca, cat, fail) != (c["nl"], c["nr"]):
            fail("a candidate's N_L, N_R are wrong")
        if (ca, cat) == (axis, at):
            fail("a candidate is the named plane")
        costs.append(sah(g, lo, hi, ca, cat, c["nl"], c["nr"])[2])
    if len(costs) != 3:
        fail("%d candidates" % len(costs))
        return None
    cheapest = min(range(3), key=lambda k: costs[k])
    if a["cheapest"] != cheapest:
        fail("cheapest is %r, expected %r (costs %s)" % (a["cheapest"], cheapest,
                                                        [float(c) for c in costs]))
    if min(abs(costs[i] - costs[k]) for i in range(3) for k in range(i + 1, 3)) < F(15, 100):
        fail("two candidates' costs within 0.15")
    # The tree as given: children are the parent's box cut at its plane; leaves hold primitives
    # whose bounds meet the leaf's box; every primitive is in some leaf.
    nodes = {n["id"]: n for n in g["tree"]}
    listed = set()
    for n in g["tree"]:
        nlo, nhi = [fr(v) for v in n["min"]], [fr(v) for v in n["max"]]
        if "children" in n:
            ax, p = AXES[n["axis"]], fr(n["position"])
            l, r = nodes[n["children"][0]], nodes[n["children"][1]]
            want_l = (nlo, [p if i == ax else nhi[i] for i in (0, 1)])
            want_r = ([p if i == ax else nlo[i] for i in (0, 1)], nhi)
            if ([fr(v) for v in l["min"]], [fr(v) for v in l["max"]]) != tuple(want_l) or \
               ([fr(v) for v in r["min"]], [fr(v) for v in r["max"]]) != tuple(want_r):
                fail("node %d's children are not its box cut at its plane" % n["id"])
        else:
            for p in n["prims"]:
                plo, phi = prims[p][2]
                if any(phi[i] < nlo[i] or plo[i] > nhi[i] for i in (0, 1)):
                    fail("leaf %d lists primitive %d outside it" % (n["id"], p))
                listed.add(p)
    if listed != set(range(len(prims))):
        fail("a primitive in no leaf")
    if level == "hard":
        root = nodes[0]
        if g["node"] not in root["children"]:
            fail("hard: the node is not a child of the root")
        ra, rp = AXES[root["axis"]], fr(root["position"])
        if any(p[2][0][ra] < rp < p[2][1][ra] for p in prims):
            fail("hard: a primitive crosses the root's plane")
    o, d = [fr(v) for v in g["origin"]], [fr(v) for v in g["dir"]]
    if any(abs(v) not in (F(1, 2), 1, 2) for v in d) or not all(on_lattice(v, 4) for v in o):
        fail("the ray's numbers are not short decimals")
    visits = test_tree(nodes, prims, o, d, root_lo, root_hi)
    if a["visits"] != visits:
        fail("visits is %r, expected %r" % (a["visits"], visits))
    if not 3 <= len(visits) <= 8:
        fail("TestTree enters %d nodes" % len(visits))
    return "empty side" if empty else "full sides"


def bvh_walk(boxes, prims, o, d):
    """raystep's BVH traversal as lesson 10 states it: a box entered when the slab test finds
    the ray in it before the nearest hit; the first child first when d along the node's axis is
    positive; every primitive of a leaf tested."""
    stack, enters, tests, closest, nid, missed_leaf = [], [], 0, F(10 ** 9), 0, False
    while True:
        b = boxes[nid]
        lo, hi = [fr(v) for v in b["min"]], [fr(v) for v in b["max"]]
        if slab(o, d, lo, hi, F(0), closest) is not None:
            enters.append(nid)
            if "children" in b:
                first, second = b["children"]
                if d[AXES[b["axis"]]] < 0:
                    first, second = second, first
                stack.append(second)
                nid = first
                continue
            any_hit = False
            for p in b["prims"]:
                tests += 1
                t = hit(prims[p], o, d)
                if t is not None and t < closest:
                    closest, any_hit = t, True
            missed_leaf = missed_leaf or not any_hit
        if not stack:
            break
        nid = stack.pop()
    return enters, tests, missed_leaf


def share_space(a, b):
    return all(min(fr(a["max"][i]), fr(b["max"][i])) > max(fr(a["min"][i]), fr(b["min"][i]))
               for i in (0, 1))


def inside(a, b):
    return all(fr(b["min"][i]) <= fr(a["min"][i]) and fr(a["max"][i]) <= fr(b["max"][i])
               for i in (0, 1))


def overlap(a, b):
    """Lesson 10's overlap: the boxes share space and neither lies inside the other."""
    return share_space(a, b) and not inside(a, b) and not inside(b, a)


def check_bvh(j, level, fail):
    g, a = j["given"], j["answers"]
    for key in ("origin", "dir", "boxes"):
        if key not in g:
            fail("given has no %s" % key)
            return None
    prims = prims_of(g)
    boxes = {b["id"]: b for b in g["boxes"]}
    # Each box bounds exactly its primitives: a leaf's the union of theirs, a node's its children's.
    seen = []

    def bounds(nid):
        b = boxes[nid]
        if "children" in b:
            parts = [bounds(c) for c in b["children"]]
        else:
            seen.extend(b["prims"])
            parts = [prims[p][2] for p in b["prims"]]
        lo = [min(p[0][i] for p in parts) for i in (0, 1)]
        hi = [max(p[1][i] for p in parts) for i in (0, 1)]
        if [fr(v) for v in b["min"]] != lo or [fr(v) for v in b["max"]] != hi:
            fail("box %d does not bound its primitives" % nid)
        for v in lo + hi:
            if not on_lattice(v, 2):
                fail("box %d's corner %s is off the half-unit lattice" % (nid, v))
        return lo, hi

    bounds(0)
    if sorted(seen) != list(range(len(prims))):
        fail("the leaves do not hold every primitive once")
    pairs = [(boxes[b["children"][0]], boxes[b["children"][1]])
             for b in g["boxes"] if "children" in b]
    overlapping = [(x["id"], y["id"]) for x, y in pairs if overlap(x, y)]
    o, d = [fr(v) for v in g["origin"]], [fr(v) for v in g["dir"]]
    if any(abs(v) not in (F(1, 2), 1, 2) for v in d) or not all(on_lattice(v, 4) for v in o):
        fail("the ray's numbers are not short decimals")
    enters, tests, missed_leaf = bvh_walk(boxes, prims, o, d)
    if a["enters"] != enters:
        fail("enters is %r, expected %r" % (a["enters"], enters))
    if a["tests"] != tests:
        fail("tests is %r, expected %r" % (a["tests"], tests))
    if not 3 <= len(enters) <= 8:
        fail("the ray enters %d boxes" % len(enters))
    if level == "easy":
        if any(share_space(x, y) for x, y in pairs):
            fail("easy: two siblings share space")
        return "easy"
    if not overlapping:
        fail("%s: no siblings overlap" % level)
    if not missed_leaf:
        fail("%s: no leaf entered whose primitives all miss" % level)
    if level == "hard" and not any(x in enters and y in enters for x, y in overlapping):
        fail("hard: the ray enters no two overlapping boxes")
    return "%d boxes" % len(boxes)


if __name__ == "__main__":
    sys.exit(practice_sweep.main(sys.argv, (("kdtree", check_kdtree), ("bvh", check_bvh)), 200, 3))

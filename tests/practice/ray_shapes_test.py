#!/usr/bin/env python3
"""An independent check of the ray-sphere and ray-triangle practice topics: every answer is
recomputed from `given` with exact fractions (no raystep code), the level rules are checked,
the same seed gives the same bytes, and the instances of a level are mostly distinct.

Usage: ray_shapes_test.py RAYSTEP_CLI [SEEDS]"""
import math
import sys
from fractions import Fraction as F

import practice_sweep

def close(got, want):
    return got is not None and abs(got - want) <= 1e-9 * max(1.0, abs(float(want)))


def sub(p, q):
    return [x - y for x, y in zip(p, q)]


def dot(p, q):
    return sum(x * y for x, y in zip(p, q))


def cross(p, q):
    return [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]]


def is_square(n):
    return n >= 0 and math.isqrt(n) ** 2 == n


def check_sphere(j, level, fail):
    g, a = j["given"], j["answers"]
    o, d, c, r = g["origin"], g["dir"], g["center"], g["radius"]
    for x in o + d + c + [r]:
        if x != int(x) or abs(x) > 6:
            fail("a coordinate is not a small whole number: %r" % x)
    o, d, c, r = [int(x) for x in o], [int(x) for x in d], [int(x) for x in c], int(r)
    if r < 1 or not any(d):
        fail("a radius below 1 or a zero direction")
    f = sub(o, c)
    A, B, C = dot(d, d), 2 * dot(d, f), dot(f, f) - r * r
    disc = B * B - 4 * A * C
    for key, want in (("B", B), ("C", C), ("discriminant", disc)):
        if not close(a[key], want):
            fail("%s is %r, expected %r" % (key, a[key], want))
    if disc == 0:
        fail("a tangent ray (discriminant 0)")
    if C == 0:
        fail("a root at t = 0 (the origin on the sphere)")
    hit = False
    t = None
    if disc > 0:
        if is_square(disc):
            s = math.isqrt(disc)
            t0, t1 = F(-B - s, 2 * A), F(-B + s, 2 * A)
        else:
            s = math.sqrt(disc)
            t0, t1 = (-B - s) / (2 * A), (-B + s) / (2 * A)
        t = t0 if t0 > 0 else t1 if t1 > 0 else None
        hit = t is not None
    if a["hit"] is not hit:
        fail("hit is %r, expected %r" % (a["hit"], hit))
    if hit and not close(a["t"], t):
        fail("t is %r, expected %r" % (a["t"], t))
    if not hit and a["t"] is not None:
        fail("t is given for a miss")
    ids = [e["id"] for e in j["exercises"]]
    if ("t" in ids) is not hit:
        fail("a t exercise %s" % ("for a miss" if not hit else "missing for a hit"))
    inside, behind = C < 0, disc > 0 and C > 0 and B > 0
    if level == "easy" and not (is_square(disc) and disc > 0 and C > 0 and hit):
        fail("easy: not a perfect square hit from outside")
    if level == "medium" and (inside or behind):
        fail("medium: from inside or a sphere behind")
    return ("inside" if inside else "behind" if behind else "hit" if hit else "miss")


def check_triangle(j, level, fail):
    g, a = j["given"], j["answers"]
    pts = [g["origin"], g["dir"], g["a"], g["b"], g["c"]]
    for x in sum(pts, []):
        if x * 2 != int(x * 2) or abs(x) > 6:
            fail("a coordinate is not a small whole or half number: %r" % x)
    if any(x != int(x) for x in g["dir"]):
        fail("the direction is not whole")
    o, d, va, vb, vc = [[F(x) for x in p] for p in pts]
    n = cross(sub(vb, va), sub(vc, va))
    nd = dot(n, d)
    if nd == 0 or dot(n, n) == 0:
        fail("a ray parallel to the plane or a degenerate triangle")
        return "bad"
    t = dot(n, sub(va, o)) / nd
    p = [oi + t * di for oi, di in zip(o, d)]
    nn = dot(n, n)
    u = dot(n, cross(sub(p, va), sub(vc, va))) / nn
    v = dot(n, cross(sub(vb, va), sub(p, va))) / nn
    w = 1 - u - v
    hit = t > 0 and u >= 0 and v >= 0 and w >= 0
    if a["hit"] is not hit:
        fail("hit is %r, expected %r" % (a["hit"], hit))
    if not close(a["t"], t):
        fail("t is %r, expected %r" % (a["t"], t))
    for key, want in (("u", u), ("v", v)):
        if t > 0 and not close(a[key], want):
            fail("%s is %r, expected %r" % (key, a[key], want))
        if t < 0 and a[key] is not None:
            fail("%s is given for a plane behind the origin" % key)
    if min(abs(u), abs(v), abs(w)) < F(2, 100):
        fail("a grazing case: within 0.02 of an edge")
    if t == 0:
        fail("t = 0")
    if level == "easy":
        if not (va[2] == vb[2] == vc[2] and d[2] < 0 and hit):
            fail("easy: not a hit on a triangle in a plane z = k from above")
        if any((x * 20).denominator != 1 for x in (t, u, v)):
            fail("easy: t, u, v are not short decimals")
    if level == "medium" and t < 0:
        fail("medium: the plane behind the origin")
    if t < 0:
        return "behind"
    return "hit" if hit else "over" if u > 0 and v > 0 else "outside"


if __name__ == "__main__":
    sys.exit(practice_sweep.main(sys.argv, (("ray-sphere", check_sphere), ("ray-triangle", check_triangle)), 150, 5))

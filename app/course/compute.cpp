// Compute exercises: the answer from raystep's kernels, the working with the given numbers, and
// the slips a wrong number betrays.
#include "course/compute.h"

#include "raystep/accel/dda.h"
#include "raystep/accel/sah.h"
#include "raystep/base/math.h"
#include "raystep/geometry/intersect.h"
#include "raystep/render/shading.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace raystep {

namespace {

using Shape = ComputeGiven::Shape;
using V3 = TVec3<double>;

V3 vec(const std::array<double, 3>& a) {
    return {a[0], a[1], a[2]};
}

/// A number in the working: the language's decimal mark, a negative one in brackets.
std::string num(double v, Language lang) {
    const std::string s = formatNumber(v == 0.0 ? 0.0 : v, lang);
    return v < 0 ? "(" + s + ")" : s;
}
/// A tuple: "(1.5, 2, 0)"; in Italian "(1,5; 2; 0)", the language's list separator.
std::string tuple(const std::array<double, 3>& v, int dims, Language lang) {
    std::string s = "(";
    for (int i = 0; i < dims; ++i) {
        if (i) s += listSeparator(lang);
        s += formatNumber(v[i] == 0.0 ? 0.0 : v[i], lang);
    }
    return s + ")";
}
std::string tuple(const V3& v, Language lang) {
    return tuple(std::array<double, 3>{v.x, v.y, v.z}, 3, lang);
}

bool close(double a, double b) {
    return std::abs(a - b) <= 0.01 * std::max(1.0, std::abs(b));
}

/// Every quantity of the exercise's shape that its data define, by name, from the kernels.
struct Evaluation {
    std::map<std::string, double> q;
    std::string undefinedWhy;  // English, for the lecturer's error message
};

Evaluation evaluate(const ComputeGiven& g) {
    Evaluation e;
    const V3 o = vec(g.o), d = vec(g.d);
    constexpr double kInf = std::numeric_limits<double>::infinity();
    switch (g.shape) {
        case Shape::Sphere: {
            StepLog log;
            const auto t =
                intersectSphereTextbook<double>(o, d, vec(g.center), g.radius, 0.0, kInf, log);
            for (const auto& s : log.steps) e.q[s.name] = s.v[0];
            if (t) e.q["t"] = *t;
            if (!e.q.count("t0"))
                e.undefinedWhy = "the ray misses the sphere (discriminant < 0)";
            else if (!t)
                e.undefinedWhy = "both roots lie behind the origin (the sphere is behind the ray)";
            break;
        }
        case Shape::Triangle: {
            StepLog log;
            intersectTrianglePlane<double>(o, d, vec(g.tri[0]), vec(g.tri[1]), vec(g.tri[2]), 0.0,
                                           kInf, log);
            for (const auto& s : log.steps)
                if (s.size == 1) e.q[s.name] = s.v[0];
            if (!e.q.count("u"))
                e.undefinedWhy =
                    "the ray is parallel to the triangle or meets "
                    "its plane behind the origin";
            break;
        }
        case Shape::Plane: {
            StepLog log;
            intersectPlane<double>(o, d, vec(g.normal), g.k, -kInf, kInf, log);
            for (const auto& s : log.steps) e.q[s.name] = s.v[0];
            if (!e.q.count("t")) e.undefinedWhy = "the ray is parallel to the plane";
            break;
        }
        case Shape::Box: {
            const auto span = intersectBox<double>(o, d, vec(g.lo), vec(g.hi), 0.0, kInf);
            if (!span) {
                e.undefinedWhy = "the ray misses the box";
                break;
            }
            e.q["t_enter"] = span->first;
            e.q["t_exit"] = span->second;
            break;
        }
        case Shape::Grid: {
            const auto walk = [&](auto dimsTag) {
                constexpr int N = decltype(dimsTag)::value;
                GridSpec<N, double> spec;
                for (int i = 0; i < N; ++i) {
                    // Without "res", a grid of 1024 cells per axis: far larger than an example.
                    spec.res[i] = g.res[i] > 0 ? g.res[i] : 1024;
                    spec.lo[i] = g.lo[i];
                    spec.hi[i] = g.lo[i] + spec.res[i] * g.hi[i];
                }
                VecN<N, double> oo, dd;
                for (int i = 0; i < N; ++i) {
                    oo[i] = g.o[i];
                    dd[i] = g.d[i];
                }
                Dda<N, double> dda(spec, oo, dd);
                if (!dda.valid()) {
                    e.undefinedWhy = "the ray misses the grid";
                    return;
                }
                for (int i = 0; i < N; ++i) {
                    const std::string a(1, "xyz"[i]);
                    e.q["cell." + a] = dda.cell()[i];
                    e.q["tMax." + a] = dda.tMax()[i];
                    e.q["tDelta." + a] = dda.tDelta()[i];
                }
                e.q["t_enter"] = dda.tEnter();
            };
            if (g.dims == 2)
                walk(std::integral_constant<int, 2>{});
            else
                walk(std::integral_constant<int, 3>{});
            break;
        }
        case Shape::Node: {
            const auto costs = [&](auto dimsTag) {
                constexpr int N = decltype(dimsTag)::value;
                BoxN<N> box;
                for (int i = 0; i < N; ++i) {
                    box.lo[i] = g.lo[i];
                    box.hi[i] = g.hi[i];
                }
                const auto [l, r] = box.splitAt(g.axis, g.at);
                e.q["area"] = box.area();
                e.q["areaL"] = l.area();
                e.q["areaR"] = r.area();
                e.q["pL"] = l.area() / box.area();
                e.q["pR"] = r.area() / box.area();
            };
            if (g.dims == 2)
                costs(std::integral_constant<int, 2>{});
            else
                costs(std::integral_constant<int, 3>{});
            e.q["sahCost"] =
                sahCost(g.cTrav, g.cIsect, g.emptyBonus, e.q["pL"], e.q["pR"],
                        static_cast<std::uint32_t>(g.nl), static_cast<std::uint32_t>(g.nr));
            break;
        }
        case Shape::Shading: {
            // The renderer's own phong() (render/shading.h), one grey channel.
            const V3 n = vec(g.normal), l = vec(g.toLight);
            const V3 v = g.specular ? vec(g.toViewer) : n;
            const PhongTerms t =
                phong(n, l, v, Color(g.intensity), Color(g.kd), Color(g.ks), g.shininess);
            e.q["n.l"] = glm::dot(n, l);
            e.q["diffuse"] = t.diffuse.x;
            if (g.specular) {
                e.q["r.v"] = glm::dot(reflect(-l, n), v);
                e.q["specular"] = t.specular.x;
            }
            break;
        }
    }
    return e;
}

const char* axisLetter(int i) {
    return i == 0 ? "x" : i == 1 ? "y" : "z";
}
int axisOf(const std::string& q) {
    return q.back() - 'x';
}

}  // namespace

double computeAnswer(const Exercise& ex, const std::string& lessonFile) {
    const Evaluation e = evaluate(ex.given);
    const auto it = e.q.find(ex.computeQuantity);
    if (it == e.q.end() || !std::isfinite(it->second))
        throw LessonError(lessonFile, ex.line, "exercises." + ex.id + ".given",
                          ex.computeQuantity + " is not defined for these data: " +
                              (e.undefinedWhy.empty() ? "it is infinite (the ray never crosses)"
                                                      : e.undefinedWhy));
    return it->second;
}

std::string computeWorking(const Exercise& ex, Language lang) {
    const ComputeGiven& g = ex.given;
    const Evaluation e = evaluate(g);
    const auto q = [&](const char* name) {
        const auto it = e.q.find(name);
        return it == e.q.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
    };
    // An operand in brackets when negative ("2 (-2) · 7"); a result or a listed value plain.
    const auto n = [&](double v) { return num(v, lang); };
    const auto v = [&](double x) { return formatNumber(x == 0.0 ? 0.0 : x, lang); };
    const std::string& what = ex.computeQuantity;
    const V3 o = vec(g.o), d = vec(g.d);
    switch (g.shape) {
        case Shape::Sphere: {
            const V3 f = o - vec(g.center);
            if (what == "a")
                return "A = d·d = " + n(d.x) + "² + " + n(d.y) + "² + " + n(d.z) +
                       "² = " + v(q("a")) + ".";
            if (what == "b")
                return "B = 2 d·(o − c) = 2 (" + n(d.x) + " · " + n(f.x) + " + " + n(d.y) + " · " +
                       n(f.y) + " + " + n(d.z) + " · " + n(f.z) + ") = " + v(q("b")) + ".";
            if (what == "c")
                return "C = |o − c|² − R² = " + n(f.x) + "² + " + n(f.y) + "² + " + n(f.z) +
                       "² − " + n(g.radius) + "² = " + v(q("c")) + ".";
            const std::string abc = "A = " + v(q("a")) + ", B = " + v(q("b")) +
                                    ", C = " + v(q("c")) + "; Δ = B² − 4AC = " + n(q("b")) +
                                    "² − 4 · " + n(q("a")) + " · " + n(q("c")) + " = " +
                                    v(q("discriminant"));
            if (what == "discriminant") return abc + ".";
            const std::string roots = abc + "; t0 = (−B − √Δ) / 2A = " + v(q("t0")) +
                                      ", t1 = (−B + √Δ) / 2A = " + v(q("t1"));
            if (what == "t0" || what == "t1") return roots + ".";
            return roots + "; " +
                   trf(lang, "t is the smaller root in front of the origin (t > 0): %1.",
                       {v(q("t"))});
        }
        case Shape::Triangle: {
            const V3 a = vec(g.tri[0]), b = vec(g.tri[1]), c = vec(g.tri[2]);
            const V3 nn = glm::cross(b - a, c - a);
            std::string s =
                "n = (b − a) × (c − a) = " + tuple(nn, lang) + "; n·d = " + v(q("n.dir"));
            if (what == "n.dir") return s + ".";
            s += "; t = (n·a − n·o) / n·d = (" + n(glm::dot(nn, a)) + " − " + n(glm::dot(nn, o)) +
                 ") / " + n(q("n.dir")) + " = " + v(q("t"));
            if (what == "t") return s + ".";
            const double t = q("t");
            const V3 p = o + t * d;
            s += "; p = o + t d = " + tuple(p, lang) + "; |n|² = " + v(glm::dot(nn, nn));
            if (what == "u") return s + "; u = n·((p − a) × (c − a)) / |n|² = " + v(q("u")) + ".";
            return s + "; v = n·((b − a) × (p − a)) / |n|² = " + v(q("v")) + ".";
        }
        case Shape::Plane: {
            const V3 nn = vec(g.normal);
            std::string s = "n·d = " + v(q("n.dir"));
            if (what == "n.dir") return s + ".";
            return s + "; t = (k − n·o) / (n·d) = (" + n(g.k) + " − " + n(glm::dot(nn, o)) +
                   ") / " + n(q("n.dir")) + " = " + v(q("t")) + ".";
        }
        case Shape::Box: {
            // t_enter's working gives the entries only: the exits would answer t_exit.
            const bool enter = what == "t_enter";
            std::string s =
                enter ? tr(lang,
                           "Per axis, the slab's entry time, the smaller of (min − o) / d and "
                           "(max − o) / d:")
                      : tr(lang, "Per axis, the slab's times (min − o) / d and (max − o) / d:");
            for (int i = 0; i < 3; ++i) {
                if (g.d[i] == 0.0) continue;
                double t0 = (g.lo[i] - g.o[i]) / g.d[i], t1 = (g.hi[i] - g.o[i]) / g.d[i];
                if (t0 > t1) std::swap(t0, t1);
                s += std::string(" ") + axisLetter(i) + " " +
                     (enter ? v(t0) : "[" + v(t0) + std::string(listSeparator(lang)) + v(t1) + "]");
            }
            return s + "; " +
                   (what == "t_enter"
                        ? trf(lang, "t_enter is the largest entry (0 if the origin is inside): %1.",
                              {v(q("t_enter"))})
                        : trf(lang, "t_exit is the smallest exit: %1.", {v(q("t_exit"))}));
        }
        case Shape::Grid: {
            const int i = axisOf(what);
            const std::string a = axisLetter(i);
            if (what.rfind("tDelta.", 0) == 0)
                return "tDelta." + a + " = " + tr(lang, "cell size") + " / |d." + a +
                       "| = " + n(g.hi[i]) + " / |" + v(g.d[i]) + "| = " + v(q(what.c_str())) + ".";
            const double tEnter = q("t_enter");
            const double p = g.o[i] + tEnter * g.d[i];
            std::string s =
                trf(lang, "The ray enters the grid at t_enter = %1, at %2 = %3 along %4",
                    {v(tEnter), a, v(p), a}) +
                "; cell." + a + " = ⌊(" + n(p) + " − " + n(g.lo[i]) + ") / " + n(g.hi[i]) + "⌋";
            // Only a point on a boundary has a cell below it to choose.
            const double across = (p - g.lo[i]) / g.hi[i];
            if (g.d[i] < 0 &&
                std::abs(across - std::round(across)) <= 1e-9 * std::max(1.0, std::abs(across)))
                s += " " + tr(lang, "(on a face, the cell below it, since d is negative)");
            s += " = " + v(q(("cell." + a).c_str()));
            if (what.rfind("cell.", 0) == 0) return s + ".";
            const double cell = q(("cell." + a).c_str());
            const double bound = g.lo[i] + (g.d[i] > 0 ? cell + 1 : cell) * g.hi[i];
            return s + "; " + trf(lang, "the next boundary ahead is at %1 = %2", {a, v(bound)}) +
                   ": tMax." + a + " = (" + n(bound) + " − " + n(g.o[i]) + ") / " + n(g.d[i]) +
                   " = " + v(q(what.c_str())) + ".";
        }
        case Shape::Node: {
            const std::string area = g.dims == 2 ? tr(lang, "perimeter") : tr(lang, "surface area");
            std::string s =
                trf(lang, "Area = the box's %1: Area(C) = %2, Area(L) = %3, Area(R) = %4",
                    {area, v(q("area")), v(q("areaL")), v(q("areaR"))});
            // pL's working leaves pR out (and pR's pL): a lesson may ask the other next.
            if (what != "pR") s += "; P(L|C) = Area(L) / Area(C) = " + v(q("pL"));
            if (what != "pL") s += (what == "pR" ? "; " : ", ");
            if (what != "pL") s += "P(R|C) = Area(R) / Area(C) = " + v(q("pR"));
            if (what != "sahCost") return s + ".";
            s +=
                "; " +
                trf(lang,
                    "cost = C_trav + C_isect (P(L|C) NL + P(R|C) NR) = %1 + %2 (%3 · %4 + %5 · %6)",
                    {n(g.cTrav), n(g.cIsect), n(q("pL")), std::to_string(g.nl), n(q("pR")),
                     std::to_string(g.nr)});
            if (g.nl == 0 || g.nr == 0)
                s += " · (1 − " + n(g.emptyBonus) + ") " + tr(lang, "(a side is empty: the bonus)");
            return s + " = " + v(q("sahCost")) + ".";
        }
        case Shape::Shading: {
            const V3 nn = vec(g.normal), l = vec(g.toLight);
            const double nl = q("n.l");
            std::string s = "n·l = " + n(nn.x) + " · " + n(l.x) + " + " + n(nn.y) + " · " + n(l.y) +
                            " + " + n(nn.z) + " · " + n(l.z) + " = " + v(nl);
            if (what == "n.l") return s + ".";
            if (what == "diffuse") {
                if (nl <= 0.0)
                    return s + "; " +
                           tr(lang,
                              "n·l ≤ 0: the light is behind the surface, so max(0, n·l) = 0 "
                              "and the diffuse term is 0.");
                return s + "; I_diff = I · k_d · max(0, n·l) = " + n(g.intensity) + " · " +
                       n(g.kd) + " · " + n(nl) + " = " + v(q("diffuse")) + ".";
            }
            const V3 r = reflect(-l, nn), eye = vec(g.toViewer);
            s += "; r = 2 (n·l) n − l = 2 · " + n(nl) + " · " + tuple(nn, lang) + " − " +
                 tuple(l, lang) + " = " + tuple(r, lang) + "; r·v = " + n(r.x) + " · " + n(eye.x) +
                 " + " + n(r.y) + " · " + n(eye.y) + " + " + n(r.z) + " · " + n(eye.z) + " = " +
                 v(q("r.v"));
            if (what == "r.v") return s + ".";
            if (nl <= 0.0)
                return s + "; " +
                       tr(lang,
                          "but n·l ≤ 0: the light is behind the surface, and raystep's phong() "
                          "gives no highlight either, whatever r·v: the specular term is 0.");
            if (q("r.v") <= 0.0)
                return s + "; " +
                       tr(lang,
                          "r·v ≤ 0: the mirrored light points away from the eye, so "
                          "max(0, r·v) = 0 and the specular term is 0.");
            return s + "; I_spec = I · k_s · max(0, r·v)^" + v(g.shininess) + " = " +
                   n(g.intensity) + " · " + n(g.ks) + " · " + n(q("r.v")) + "^" + v(g.shininess) +
                   " = " + v(q("specular")) + ".";
        }
    }
    return "";
}

std::string computeSlip(const Exercise& ex, double given, Language lang) {
    const ComputeGiven& g = ex.given;
    const Evaluation e = evaluate(g);
    const std::string& what = ex.computeQuantity;
    const auto it = e.q.find(what);
    if (it == e.q.end()) return "";
    const double right = it->second;
    if (close(given, right)) return "";
    const auto q = [&](const char* name) {
        const auto f = e.q.find(name);
        return f == e.q.end() ? std::numeric_limits<double>::quiet_NaN() : f->second;
    };
    const auto n = [&](double v) { return formatNumber(v, lang); };
    const V3 o = vec(g.o), d = vec(g.d);
    switch (g.shape) {
        case Shape::Sphere: {
            const V3 f = o - vec(g.center);
            const double r2 = g.radius * g.radius;
            const double a = q("a"), b = q("b");
            // The slide writes C = ||dir - c||^2: the direction instead of the origin, no -R^2.
            const V3 fd = d - vec(g.center);
            if (what == "c" && close(given, glm::dot(f, f)))
                return trf(lang, "%1 is |o − c|² without − R²: C = |o − c|² − R² = %2.",
                           {n(given), n(right)});
            if (what == "c" &&
                (close(given, glm::dot(fd, fd)) || close(given, glm::dot(fd, fd) - r2)))
                return trf(lang,
                           "%1 uses the direction d where the origin o belongs (the slide's C = "
                           "||dir − c||² is a typo): C = |o − c|² − R².",
                           {n(given)});
            if (what == "discriminant" && close(given, b * b - 4 * a * glm::dot(f, f)))
                return trf(lang, "%1 is B² − 4AC with C = |o − c|², without − R².", {n(given)});
            if (what == "discriminant" && close(given, b * b - a * q("c")))
                return trf(lang, "%1 is B² − AC: the discriminant is B² − 4AC.", {n(given)});
            // The half-b form (b = B/2: t = (-b -+ sqrt(b^2 - AC)) / A) mixed with the textbook's.
            if (what == "b" && b != 0.0 && close(given, b / 2))
                return trf(lang,
                           "%1 is d·(o − c), the half-b form's b = B/2: the textbook quadratic's B "
                           "is 2 d·(o − c).",
                           {n(given)});
            if (what == "discriminant" && right != 0.0 && close(given, right / 4))
                return trf(lang,
                           "%1 is b² − AC with b = B/2, the half-b form's discriminant: a quarter "
                           "of B² − 4AC.",
                           {n(given)});
            if (what == "t0" || what == "t1" || what == "t") {
                const double t0 = q("t0"), t1 = q("t1");
                const double other = close(right, t0) ? t1 : t0;
                if (close(given, other))
                    return trf(lang,
                               "%1 is the other root: of t0, where the ray enters the sphere, and "
                               "t1, where it leaves, the intersection is the smaller root in "
                               "front of the origin.",
                               {n(given)});
                const double sq = std::sqrt(std::max(0.0, q("discriminant")));
                for (const double unhalved : {-b - sq, -b + sq}) {
                    if (close(given, unhalved))
                        return trf(lang,
                                   "%1 is −B ∓ √Δ without the division by 2A (the slide leaves out "
                                   "/2A): divide by 2A = %2.",
                                   {n(given), n(2 * a)});
                    // Half the division: by 2 or by A alone (the same when A = 2).
                    if (close(given, unhalved / 2))
                        return trf(lang,
                                   "%1 is (−B ∓ √Δ) / 2: divided by 2 but not by A = %2 (d is not "
                                   "a unit vector): t = (−B ∓ √Δ) / 2A.",
                                   {n(given), n(a)});
                    if (close(given, unhalved / a))
                        return trf(lang,
                                   "%1 is (−B ∓ √Δ) / A: divided by A but not by 2: t = (−B ∓ √Δ) "
                                   "/ 2A.",
                                   {n(given)});
                    if (close(given, unhalved / (4 * a)))
                        return trf(lang,
                                   "%1 is half the root: with the half-b form (b = B/2 = %2) the "
                                   "root is (−b ∓ √(b² − AC)) / A, divided by A alone; dividing by "
                                   "2A halves it.",
                                   {n(given), n(b / 2)});
                }
            }
            break;
        }
        case Shape::Triangle:
            if (what == "u" && close(given, q("v")))
                return trf(lang,
                           "%1 is v, not u: u weighs corner b, v corner c (p = (1 − u − v) a + u b "
                           "+ v c).",
                           {n(given)});
            if (what == "v" && close(given, q("u")))
                return trf(lang,
                           "%1 is u, not v: u weighs corner b, v corner c (p = (1 − u − v) a + u b "
                           "+ v c).",
                           {n(given)});
            break;
        case Shape::Plane:
            if (what == "t") {
                // The slide's t = -(o.n + d) / (dir.n), against its own plane p.n - d = 0.
                const V3 nn = vec(g.normal);
                if (close(given, -(glm::dot(o, nn) + g.k) / q("n.dir")))
                    return trf(
                        lang,
                        "%1 follows the slide's t = −(o·n + d) / (dir·n), whose sign contradicts "
                        "its own plane p·n − d = 0: with p·n = k, t = (k − o·n) / (d·n).",
                        {n(given)});
            }
            break;
        case Shape::Box:
            if (what == "t_enter" && close(given, q("t_exit")))
                return trf(lang,
                           "%1 is t_exit: the ray enters at the largest of the slabs' entries.",
                           {n(given)});
            if (what == "t_exit" && close(given, q("t_enter")))
                return trf(lang,
                           "%1 is t_enter: the ray leaves at the smallest of the slabs' exits.",
                           {n(given)});
            {
                // The smallest entry (or largest exit): one slab, not the box.
                double minEnter = std::numeric_limits<double>::infinity(), maxExit = -minEnter;
                for (int i = 0; i < 3; ++i) {
                    if (g.d[i] == 0.0) continue;
                    double t0 = (g.lo[i] - g.o[i]) / g.d[i], t1 = (g.hi[i] - g.o[i]) / g.d[i];
                    if (t0 > t1) std::swap(t0, t1);
                    minEnter = std::min(minEnter, t0);
                    maxExit = std::max(maxExit, t1);
                }
                if ((what == "t_enter" && close(given, minEnter)) ||
                    (what == "t_exit" && close(given, maxExit)))
                    return trf(lang,
                               "%1 is where the ray crosses one slab, not the box: the box is the "
                               "overlap of the three slabs.",
                               {n(given)});
            }
            break;
        case Shape::Grid: {
            const int i = axisOf(what);
            const std::string a = axisLetter(i);
            if (what.rfind("cell.", 0) == 0 && g.d[i] < 0 && std::abs(given - right) == 1.0)
                return trf(lang,
                           "%1 is one cell off: with d.%2 negative, the ray on a boundary is in "
                           "the cell below it, and the index counts down from there.",
                           {n(given), a});
            if (what.rfind("tMax.", 0) == 0) {
                const double cell = q(("cell." + a).c_str());
                const double wrongBound = g.lo[i] + (g.d[i] > 0 ? cell : cell + 1) * g.hi[i];
                if (close(given, (wrongBound - g.o[i]) / g.d[i]))
                    return trf(
                        lang,
                        "%1 uses the boundary behind the ray: the next boundary ahead is at %2 = "
                        "%3.",
                        {n(given), a, n(g.lo[i] + (g.d[i] > 0 ? cell + 1 : cell) * g.hi[i])});
            }
            break;
        }
        case Shape::Node:
            if (what == "pL" || what == "pR" || what == "sahCost") {
                const double pl2 = q("pL") * q("pL"), pr2 = q("pR") * q("pR");
                const double cost2 =
                    sahCost(g.cTrav, g.cIsect, g.emptyBonus, pl2, pr2,
                            static_cast<std::uint32_t>(g.nl), static_cast<std::uint32_t>(g.nr));
                if ((what == "pL" && close(given, pl2)) || (what == "pR" && close(given, pr2)) ||
                    (what == "sahCost" && close(given, cost2)))
                    return trf(lang,
                               "%1 takes the probability as Area²/Area² (the slide's slip): P(L|C) "
                               "is Area(L) / Area(C), not squared.",
                               {n(given)});
            }
            if (what == "sahCost" && (g.nl == 0 || g.nr == 0) &&
                close(given, splitCost(g.cTrav, g.cIsect, q("pL"), q("pR"), g.nl, g.nr)))
                return trf(lang,
                           "%1 leaves out the empty-space bonus: a side is empty, so the cost is "
                           "multiplied by (1 − %2).",
                           {n(given), n(g.emptyBonus)});
            if (what == "sahCost" && g.nl && g.nr && close(given, (1.0 - g.emptyBonus) * right))
                return trf(lang, "%1 applies the empty-space bonus, but neither side is empty.",
                           {n(given)});
            break;
        case Shape::Shading: {
            const V3 nn = vec(g.normal), l = vec(g.toLight);
            const double nl = q("n.l");
            if (what == "diffuse" && nl < 0.0 && close(given, g.intensity * g.kd * nl))
                return trf(lang,
                           "%1 is I · k_d · n·l without the clamp: with n·l < 0 the light is "
                           "behind the surface, and max(0, n·l) = 0.",
                           {n(given)});
            if (what == "diffuse" && g.intensity != 1.0 && close(given, g.kd * std::max(0.0, nl)))
                return trf(lang, "%1 leaves out the light's intensity I.", {n(given)});
            if (!g.specular) break;
            const V3 eye = vec(g.toViewer);
            const double rv = q("r.v");
            const auto spec = [&](double cosine) {
                return g.intensity * g.ks * std::pow(std::max(0.0, cosine), g.shininess);
            };
            if (what == "r.v" && close(given, glm::dot(l, eye)) && !close(rv, glm::dot(l, eye)))
                return trf(lang,
                           "%1 is l·v: the light's direction itself, not mirrored about the "
                           "normal (r = 2 (n·l) n − l).",
                           {n(given)});
            if (what == "r.v" && close(given, glm::dot(nn, eye)) && !close(rv, glm::dot(nn, eye)))
                return trf(lang, "%1 is n·v: the specular term takes the mirrored light r, not n.",
                           {n(given)});
            if (what != "specular") break;
            if (nl <= 0.0 && given > 0.0 && close(given, spec(rv)))
                return trf(lang,
                           "%1 gives the light behind the surface a highlight: with n·l ≤ 0 "
                           "raystep's phong() gives neither term.",
                           {n(given)});
            if (rv < 0.0 && close(given, g.intensity * g.ks * std::pow(rv, g.shininess)))
                return trf(lang,
                           "%1 raises a negative r·v to the power: the clamp max(0, r·v) makes "
                           "it 0.",
                           {n(given)});
            if (g.shininess != 1.0 && rv > 0.0 && close(given, g.intensity * g.ks * rv))
                return trf(lang, "%1 leaves out the shininess exponent: (r·v)^%2.",
                           {n(given), n(g.shininess)});
            if (close(given, spec(glm::dot(nn, eye))) && !close(right, spec(glm::dot(nn, eye))))
                return trf(lang, "%1 takes n·v for the cosine: the specular term's is r·v.",
                           {n(given)});
            if (close(given, spec(glm::dot(l, eye))) && !close(right, spec(glm::dot(l, eye))))
                return trf(lang,
                           "%1 takes l·v for the cosine: the light's direction mirrored about the "
                           "normal, r = 2 (n·l) n − l, goes in the specular term.",
                           {n(given)});
            break;
        }
    }
    if (right != 0.0 && close(given, -right))
        return trf(lang, "%1 has the wrong sign.", {n(given)});
    return "";
}

std::vector<double> numbersInText(std::string_view text, Language lang) {
    std::vector<double> out;
    const auto digit = [&](std::size_t i) {
        return i < text.size() && text[i] >= '0' && text[i] <= '9';
    };
    for (std::size_t i = 0; i < text.size();) {
        if (!digit(i)) {
            ++i;
            continue;
        }
        // A number's start: digits not glued to a letter or a digit before them ("x2" is a name).
        const bool glued =
            i > 0 && (std::isalnum(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_');
        std::size_t j = i;
        std::string s;
        while (digit(j)) s += text[j++];
        // The language's decimal mark, or a point (a number pasted from elsewhere).
        const std::string_view mark = decimalMark(lang);
        const std::size_t markSize = text.compare(j, mark.size(), mark) == 0 ? mark.size()
                                     : j < text.size() && text[j] == '.'     ? 1
                                                                             : 0;
        if (markSize && digit(j + markSize)) {
            s += '.';
            j += markSize;
            while (digit(j)) s += text[j++];
        }
        if (j < text.size() && (text[j] == 'e' || text[j] == 'E') &&
            (digit(j + 1) || ((text[j + 1] == '-' || text[j + 1] == '+') && digit(j + 2)))) {
            s += text[j++];
            while (j < text.size() && (digit(j) || text[j] == '-' || text[j] == '+'))
                s += text[j++];
        }
        if (!glued) {
            double v = std::strtod(s.c_str(), nullptr);
            // A minus sign before it: '-' or the Unicode minus U+2212 (E2 88 92).
            if (i >= 1 && text[i - 1] == '-') v = -v;
            if (i >= 3 && text.substr(i - 3, 3) == "\xe2\x88\x92") v = -v;
            out.push_back(v);
        }
        i = j;
    }
    return out;
}

std::vector<double> numbersNotInText(const std::vector<double>& numbers, std::string_view text,
                                     Language lang) {
    const std::vector<double> written = numbersInText(text, lang);
    std::vector<double> missing;
    for (const double v : numbers)
        if (std::none_of(written.begin(), written.end(), [&](double w) {
                return std::abs(w - v) <= 1e-9 * std::max(1.0, std::abs(v));
            }))
            missing.push_back(v);
    return missing;
}

}  // namespace raystep

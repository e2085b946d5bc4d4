// Practice on the slides' ray-triangle intersection: meet the plane (t), then the barycentric
// u, v of the point, and hit or miss. easy: a triangle in a plane z = k, a ray going down, short
// decimals; medium: any plane, misses outside the triangle too; hard: the plane met behind the
// origin, or u + v just above 1. Never a ray parallel to the plane, nor a grazing case.
#include "course/practice/generator.h"

#include "raystep/geometry/intersect.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace raystep::practice {

namespace {

enum class Case { Inside, Outside, Behind, JustOver };

using V3 = TVec3<double>;

struct TriData {
    V3 o, d, a, b, c;
    double t = 0, u = 0, v = 0;
};

std::vector<double> asVec(const V3& p) {
    return {p.x, p.y, p.z};
}

/// A multiple of `step`, to 1e-9.
bool multipleOf(double x, double step) {
    return std::abs(x / step - std::round(x / step)) < 1e-9;
}

double halves(double x) {
    return std::round(x * 2.0) / 2.0;
}

TriData drawTriangle(Random& r, PracticeLevel level, Case want) {
    const bool easy = level == PracticeLevel::Easy;
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (;;) {
        TriData g;
        const int k = r.between(-2, 2);
        const auto vertex = [&] {
            if (easy) return V3(r.between(-4, 4), r.between(-4, 4), k);
            return V3(r.between(-4, 4), r.between(-4, 4), r.between(-4, 4));
        };
        g.a = vertex();
        g.b = vertex();
        g.c = vertex();
        const V3 n = glm::cross(g.b - g.a, g.c - g.a);
        if (glm::dot(n, n) < 16.0) continue;  // degenerate or too thin to read
        if (easy)
            g.d = V3(r.between(-1, 1), r.between(-1, 1), -r.between(1, 2));
        else
            g.d = V3(r.between(-3, 3), r.between(-3, 3), r.between(-3, 3));
        // Not parallel, nor nearly: |cos| of the angle between d and n at least 0.2.
        const double nd = glm::dot(n, g.d);
        if (nd * nd < 0.04 * glm::dot(n, n) * glm::dot(g.d, g.d)) continue;
        // Aim at a point of the plane with the barycentrics the case wants (in tenths).
        double tu = r.between(1, 8) / 10.0, tv = r.between(1, 8) / 10.0;
        if (want == Case::Outside) (r.chance(50) ? tu : tv) = -r.between(1, 5) / 10.0;
        if (want == Case::JustOver) tv = 1.1 - tu;
        const V3 q = g.a + tu * (g.b - g.a) + tv * (g.c - g.a);
        const double s = r.between(1, 3) * (want == Case::Behind ? -1.0 : 1.0);
        g.o = q - s * g.d;
        for (int i = 0; i < 3; ++i) g.o[i] = easy ? std::round(g.o[i]) : halves(g.o[i]);
        if (std::max({std::abs(g.o.x), std::abs(g.o.y), std::abs(g.o.z)}) > 6.0) continue;
        // t, u, v from the slides' kernel, with the plane met anywhere along the line.
        StepLog log;
        intersectTrianglePlane<double>(g.o, g.d, g.a, g.b, g.c, -kInf, kInf, log);
        bool haveU = false, haveV = false, haveT = false;
        for (const auto& st : log.steps) {
            const std::string name = st.name;
            if (name == "t") g.t = st.v[0], haveT = true;
            if (name == "u") g.u = st.v[0], haveU = true;
            if (name == "v") g.v = st.v[0], haveV = true;
        }
        if (!haveT || !haveU || !haveV) continue;
        // No grazing case: the point at least 0.02 from every edge, t clear of 0.
        const double w = 1.0 - g.u - g.v;
        if (std::abs(g.u) < 0.02 || std::abs(g.v) < 0.02 || std::abs(w) < 0.02) continue;
        if (std::abs(g.t) < 0.1) continue;
        const bool inside = g.u > 0 && g.v > 0 && w > 0;
        bool fits = false;
        switch (want) {
            case Case::Inside:
                fits = inside && g.t > 0;
                break;
            case Case::Outside:
                fits = !inside && g.t > 0 && (g.u < 0 || g.v < 0);
                break;
            case Case::Behind:
                fits = g.t < 0;
                break;
            case Case::JustOver:
                fits = g.t > 0 && g.u > 0 && g.v > 0 && w < 0 && w > -0.2;
                break;
        }
        if (easy && !(multipleOf(g.t, 0.05) && multipleOf(g.u, 0.05) && multipleOf(g.v, 0.05)))
            fits = false;
        if (fits) return g;
    }
}

}  // namespace

Draft makeRayTriangle(Random& r, PracticeLevel level) {
    Case want = Case::Inside;
    if (level == PracticeLevel::Medium) want = r.chance(33) ? Case::Outside : Case::Inside;
    if (level == PracticeLevel::Hard) {
        const int k = r.between(1, 4);
        want = k == 1   ? Case::Inside
               : k == 2 ? Case::Outside
               : k == 3 ? Case::Behind
                        : Case::JustOver;
    }
    const TriData g = drawTriangle(r, level, want);
    // Hit or miss as raystep's kernel decides it (t > 0 and the point inside).
    const bool hit = intersectTrianglePlane<double>(g.o, g.d, g.a, g.b, g.c, 0.0,
                                                    std::numeric_limits<double>::infinity())
                         .has_value();
    const bool front = g.t > 0;

    const auto data = [&](bool it) {
        const std::string ray = "`o = " + vec(asVec(g.o)) + "`, `d = " + vec(asVec(g.d)) + "`";
        const std::string tri = "`a = " + vec(asVec(g.a)) + "`, `b = " + vec(asVec(g.b)) +
                                "`, `c = " + vec(asVec(g.c)) + "`";
        if (it) return "Il raggio " + ray + " e il triangolo " + tri + ".";
        return "The ray " + ray + " and the triangle " + tri + ".";
    };
    const std::string en = data(false), it = data(true);
    ojson given;
    given["ray"] = {{"o", jsonVec(asVec(g.o))}, {"d", jsonVec(asVec(g.d))}};
    given["triangle"] = {jsonVec(asVec(g.a)), jsonVec(asVec(g.b)), jsonVec(asVec(g.c))};
    const auto compute = [&](const std::string& id, double value, const std::string& askEn,
                             const std::string& askIt) {
        const bool exact = multipleOf(value, 0.01);
        ojson e =
            computeExercise(id, id, given,
                            text(en + " " + askEn + (exact ? "" : " Give it to two decimals."),
                                 it + " " + askIt + (exact ? "" : " Arrotonda a due decimali.")));
        if (!exact) e["tolerance"] = 0.005;
        return e;
    };

    Draft dr;
    ojson& l = dr.lesson;
    l["title"] =
        text("Practice: ray-triangle intersection", "Esercitazione: intersezione raggio-triangolo");
    l["text"] = text(en + " First meet the triangle's plane, with `n = (b - a) x (c - a)`; then "
                          "write the point as `p = (1 - u - v) a + u b + v c`. Work each answer "
                          "by hand, then check it.",
                     it + " Prima si interseca il piano del triangolo, con "
                          "`n = (b - a) x (c - a)`; poi si scrive il punto come "
                          "`p = (1 - u - v) a + u b + v c`. Ricava ogni risposta a mano, poi "
                          "verificala.");
    const V3 mid = (g.a + g.b + g.c) / 3.0;
    const V3 eye = mid + V3(3.0, 9.0, 16.0);
    ojson scene;
    scene["description"] = "practice: one triangle";
    scene["camera"] = {{"eye", jsonVec(asVec(eye))}, {"look_at", jsonVec(asVec(mid))}};
    scene["lights"] = {{{"position", jsonVec(asVec(eye))}}};
    scene["objects"] = {
        {{"type", "triangle"},
         {"vertices", {jsonVec(asVec(g.a)), jsonVec(asVec(g.b)), jsonVec(asVec(g.c))}}}};
    l["scene"] = scene;
    l["setup"] = {{"accel", "bruteforce"}};
    l["trace"] = {{"ray", jsonVec({g.o.x, g.o.y, g.o.z, g.d.x, g.d.y, g.d.z})}};
    l["views"] = {"3d"};

    ojson ex = ojson::array();
    ojson et = compute("t", g.t, "At what t does the ray meet the triangle's plane?",
                       "A quale t il raggio incontra il piano del triangolo?");
    et["hint"] = hints({text("`t = (n.a - n.o) / (n.d)`", "`t = (n.a - n.o) / (n.d)`")});
    ex.push_back(et);
    if (front) {
        // u and v of a point behind the origin are not the kernel's: it stops at t.
        ojson eu = compute("u", g.u, "Compute the barycentric `u` of the point where it meets it.",
                           "Calcola la coordinata baricentrica `u` del punto in cui lo incontra.");
        eu["hint"] = hints({text("`p = o + t d`, `u = n.((p - a) x (c - a)) / n.n`",
                                 "`p = o + t d`, `u = n.((p - a) x (c - a)) / n.n`")});
        ex.push_back(eu);
        ojson ev = compute("v", g.v, "Compute the barycentric `v` of the point where it meets it.",
                           "Calcola la coordinata baricentrica `v` del punto in cui lo incontra.");
        ev["hint"] =
            hints({text("`v = n.((b - a) x (p - a)) / n.n`", "`v = n.((b - a) x (p - a)) / n.n`")});
        ex.push_back(ev);
    }
    ojson ch = exercise(
        "hit", "choice",
        text(en + " Does the ray hit the triangle?", it + " Il raggio colpisce il triangolo?"));
    const ojson hitWhy = text(
        "A hit: the plane is met in front of the origin (t > 0) at a point inside the triangle, "
        "u >= 0, v >= 0 and u + v <= 1.",
        "Il raggio colpisce il triangolo: incontra il piano davanti all'origine (t > 0) in un "
        "punto interno, u >= 0, v >= 0 e u + v <= 1.");
    const ojson missWhy = text(
        "A miss: the plane is met behind the origin (t < 0), or the point is outside the "
        "triangle (u < 0, v < 0 or u + v > 1).",
        "Il raggio manca il triangolo: incontra il piano dietro l'origine (t < 0), oppure il "
        "punto è esterno al triangolo (u < 0, v < 0 oppure u + v > 1).");
    ch["choices"] = {
        {{"text", text("The ray hits the triangle", "Il raggio colpisce il triangolo")},
         {"why", hitWhy}},
        {{"text", text("The ray misses the triangle", "Il raggio manca il triangolo")},
         {"why", missWhy}}};
    ch["answer"] = hit ? 0 : 1;
    ex.push_back(ch);
    l["exercises"] = ex;

    dr.given = {{"origin", jsonVec(asVec(g.o))},
                {"dir", jsonVec(asVec(g.d))},
                {"a", jsonVec(asVec(g.a))},
                {"b", jsonVec(asVec(g.b))},
                {"c", jsonVec(asVec(g.c))}};
    dr.answers = [front](const Reference& ref) {
        ojson a = {{"hit", ref.choice("hit") == 0}, {"t", ref.number("t")}};
        a["u"] = front ? ojson(ref.number("u")) : ojson(nullptr);
        a["v"] = front ? ojson(ref.number("v")) : ojson(nullptr);
        return a;
    };
    return dr;
}

}  // namespace raystep::practice

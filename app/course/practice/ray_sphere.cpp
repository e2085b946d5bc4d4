// Practice on the slides' ray-sphere intersection: the quadratic's B, C and discriminant, hit or
// miss, and the t of the hit, with small whole numbers a student works by hand. easy: a perfect
// square discriminant, from outside, in front; medium: any discriminant, misses too; hard: from
// inside (the far root) and a sphere behind the ray. Never a tangent ray nor a root at t = 0.
#include "course/practice/generator.h"

#include "raystep/geometry/intersect.h"

#include <cmath>
#include <limits>

namespace raystep::practice {

namespace {

enum class Case { Front, Miss, Inside, Behind };

struct SphereData {
    std::array<int, 3> o{}, d{}, c{};
    int r = 1;
    long b = 0, cc = 0, disc = 0;
};

bool perfectSquare(long v) {
    if (v < 0) return false;
    const long s = std::lround(std::sqrt(static_cast<double>(v)));
    return s * s == v;
}

std::vector<double> asVec(const std::array<int, 3>& a) {
    return {double(a[0]), double(a[1]), double(a[2])};
}

/// A ray aimed near the centre (or away from it, for a sphere behind) until the case fits.
SphereData drawSphere(Random& r, PracticeLevel level, Case want) {
    for (;;) {
        SphereData g;
        g.r = r.between(1, 4);
        for (int k = 0; k < 3; ++k) g.c[k] = r.between(-3, 3);
        bool zero = true;
        for (int k = 0; k < 3; ++k) {
            g.d[k] = r.between(-3, 3);
            zero = zero && g.d[k] == 0;
        }
        if (zero) continue;
        const int s = want == Case::Behind ? -r.between(2, 3) : r.between(2, 3);
        bool inRange = true;
        for (int k = 0; k < 3; ++k) {
            const int spread = want == Case::Miss ? g.r + 2 : g.r;
            const int e = r.between(-spread, spread);
            g.o[k] = want == Case::Inside ? g.c[k] + r.between(-1, 1) : g.c[k] - s * g.d[k] + e;
            inRange = inRange && g.o[k] >= -6 && g.o[k] <= 6;
        }
        if (!inRange) continue;
        long a = 0, bh = 0, ff = 0;
        for (int k = 0; k < 3; ++k) {
            const long f = g.o[k] - g.c[k];
            a += long(g.d[k]) * g.d[k];
            bh += long(g.d[k]) * f;
            ff += f * f;
        }
        g.b = 2 * bh;
        g.cc = ff - long(g.r) * g.r;
        g.disc = g.b * g.b - 4 * a * g.cc;
        // No tangent ray and no root at t = 0: neither is a case to work by hand.
        if (g.disc == 0 || g.cc == 0) continue;
        bool fits = false;
        switch (want) {
            case Case::Front:
                fits = g.disc > 0 && g.cc > 0 && g.b < 0;
                break;
            case Case::Miss:
                fits = g.disc < 0;
                break;
            case Case::Inside:
                fits = g.cc < 0;
                break;
            case Case::Behind:
                fits = g.disc > 0 && g.cc > 0 && g.b > 0;
                break;
        }
        if (level == PracticeLevel::Easy && !perfectSquare(g.disc)) fits = false;
        if (fits) return g;
    }
}

}  // namespace

Draft makeRaySphere(Random& r, PracticeLevel level) {
    Case want = Case::Front;
    if (level == PracticeLevel::Medium) want = r.chance(33) ? Case::Miss : Case::Front;
    if (level == PracticeLevel::Hard) {
        const int k = r.between(1, 4);
        want = k == 1 ? Case::Front : k == 2 ? Case::Miss : k == 3 ? Case::Inside : Case::Behind;
    }
    const SphereData g = drawSphere(r, level, want);
    using V3 = TVec3<double>;
    const V3 o(g.o[0], g.o[1], g.o[2]), d(g.d[0], g.d[1], g.d[2]), c(g.c[0], g.c[1], g.c[2]);
    // Hit or miss as raystep's kernel decides it, never by this file's own arithmetic.
    const auto hitT = intersectSphereTextbook<double>(o, d, c, double(g.r), 0.0,
                                                      std::numeric_limits<double>::infinity());
    const bool hit = hitT.has_value();
    // "To two decimals" unless t is exact in hundredths (a perfect square may still give 5/3).
    const bool exact =
        hit && std::abs(*hitT * 100.0 - std::round(*hitT * 100.0)) < 1e-9 && perfectSquare(g.disc);

    const auto data = [&](bool it) {
        const std::string ray = "`o = " + vec(asVec(g.o)) + "`, `d = " + vec(asVec(g.d)) + "`";
        const std::string sph = "`c = " + vec(asVec(g.c)) + "`, `R = " + num(g.r, it) + "`";
        if (it)
            return "Il raggio " + ray + " (d non unitario) e la sfera di centro e raggio " + sph +
                   ".";
        return "The ray " + ray + " (d not of unit length) and the sphere with centre and radius " +
               sph + ".";
    };
    const std::string en = data(false), it = data(true);
    ojson given;
    given["ray"] = {{"o", jsonVec(asVec(g.o))}, {"d", jsonVec(asVec(g.d))}};
    given["sphere"] = {{"c", jsonVec(asVec(g.c))}, {"r", g.r}};
    const auto compute = [&](const std::string& id, const std::string& quantity,
                             const std::string& askEn, const std::string& askIt) {
        return computeExercise(id, quantity, given, text(en + " " + askEn, it + " " + askIt));
    };

    Draft dr;
    ojson& l = dr.lesson;
    l["title"] =
        text("Practice: ray-sphere intersection", "Esercitazione: intersezione raggio-sfera");
    l["text"] = text(en + " Put the ray into the sphere's equation, `|o + t d - c|^2 = R^2`: a "
                          "quadratic `A t^2 + B t + C = 0`. Work each answer by hand, then check "
                          "it.",
                     it + " Sostituisci il raggio nell'equazione della sfera, "
                          "`|o + t d - c|^2 = R^2`: una quadratica `A t^2 + B t + C = 0`. Ricava "
                          "ogni risposta a mano, poi verificala.");
    ojson scene;
    const V3 eye = c + V3(0.0, 2.0 * g.r + 6.0, 4.0 * g.r + 12.0);
    scene["description"] = "practice: one sphere";
    scene["camera"] = {{"eye", jsonVec({eye.x, eye.y, eye.z})}, {"look_at", jsonVec(asVec(g.c))}};
    scene["lights"] = {{{"position", jsonVec({eye.x, eye.y, eye.z})}}};
    scene["objects"] = {{{"type", "sphere"}, {"center", jsonVec(asVec(g.c))}, {"radius", g.r}}};
    l["scene"] = scene;
    l["setup"] = {{"accel", "bruteforce"}};
    l["trace"] = {{"ray", jsonVec({o.x, o.y, o.z, d.x, d.y, d.z})}};
    l["views"] = {"3d"};

    ojson ex = ojson::array();
    ojson eb = compute("b", "b", "Compute `B`.", "Calcola `B`.");
    eb["hint"] = hints({text("`B = 2 d.(o - c)`", "`B = 2 d.(o - c)`")});
    ex.push_back(eb);
    ojson ec = compute("c", "c", "Compute `C`.", "Calcola `C`.");
    ec["hint"] = hints({text("`C = |o - c|^2 - R^2`", "`C = |o - c|^2 - R^2`")});
    ex.push_back(ec);
    ojson ed = compute("discriminant", "discriminant", "Compute the discriminant `B^2 - 4AC`.",
                       "Calcola il discriminante `B^2 - 4AC`.");
    ed["hint"] = hints({text("`A = d.d`; then `B^2 - 4AC`.", "`A = d.d`; poi `B^2 - 4AC`.")});
    ex.push_back(ed);
    ojson ch = exercise("hit", "choice",
                        text(en + " Does the ray hit the sphere (at some t > 0)?",
                             it + " Il raggio colpisce la sfera (per qualche t > 0)?"));
    const ojson hitWhy = text(
        "A hit needs a discriminant > 0 and a root with t > 0: from outside the smaller "
        "one, from inside (C < 0) the larger.",
        "Per colpire servono un discriminante > 0 e una radice con t > 0: da fuori la più "
        "piccola, da dentro (C < 0) la più grande.");
    const ojson missWhy = text(
        "A miss: a negative discriminant (the line passes the sphere by), or both roots "
        "t < 0 (the sphere is behind the origin).",
        "Il raggio manca la sfera: discriminante negativo (la retta non interseca la sfera), "
        "oppure entrambe le radici con t < 0 (la sfera è dietro l'origine).");
    ch["choices"] = {
        {{"text", text("The ray hits the sphere", "Il raggio colpisce la sfera")}, {"why", hitWhy}},
        {{"text", text("The ray misses the sphere", "Il raggio manca la sfera")},
         {"why", missWhy}}};
    ch["answer"] = hit ? 0 : 1;
    ex.push_back(ch);
    if (hit) {
        const std::string roundEn = exact ? "" : " Give it to two decimals.";
        const std::string roundIt = exact ? "" : " Arrotonda a due decimali.";
        ojson et = compute("t", "t", "At what t does the ray first meet the sphere?" + roundEn,
                           "A quale t il raggio incontra per la prima volta la sfera?" + roundIt);
        if (!exact) et["tolerance"] = 0.005;
        et["hint"] =
            hints({text("`t = (-B -+ sqrt(B^2 - 4AC)) / 2A`: the smaller root with t > 0.",
                        "`t = (-B -+ sqrt(B^2 - 4AC)) / 2A`: la radice più piccola con t > 0.")});
        ex.push_back(et);
    }
    l["exercises"] = ex;

    dr.given = {{"origin", jsonVec(asVec(g.o))},
                {"dir", jsonVec(asVec(g.d))},
                {"center", jsonVec(asVec(g.c))},
                {"radius", g.r}};
    dr.answers = [hit](const Reference& ref) {
        ojson a = {{"B", ref.number("b")},
                   {"C", ref.number("c")},
                   {"discriminant", ref.number("discriminant")},
                   {"hit", ref.choice("hit") == 0}};
        a["t"] = hit ? ojson(ref.number("t")) : ojson(nullptr);
        return a;
    };
    return dr;
}

}  // namespace raystep::practice

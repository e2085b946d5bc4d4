// Practice on the slides' local model (Phong) at one hit point: n.l, the diffuse term, the
// light mirrored about the normal and r.v, the specular term, with unit vectors whose components
// are 0, 0.6, 0.8 or 1 (Pythagorean triples) so a student works them by hand. easy: diffuse
// only, the light in front; medium: the specular term too; hard: the light behind the surface
// (both terms 0) or the mirrored light turned away from the eye (r.v < 0, no highlight). The
// answers are compute exercises: raystep's phong() (render/shading.h) gives them.
#include "course/practice/generator.h"

#include <cmath>
#include <cstdlib>

namespace raystep::practice {

namespace {

using V = std::array<long, 3>;  // a unit vector in hundredths

long dot4(const V& a, const V& b) {  // in ten-thousandths
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// The unit vectors (0, 0, ±1) and (0, ±0.6, ±0.8), (0, ±0.8, ±0.6) in every axis order.
const std::vector<V>& unitVectors() {
    static const std::vector<V> list = [] {
        std::vector<V> out;
        for (const V base : {V{0, 0, 100}, V{0, 60, 80}, V{0, 80, 60}})
            for (const std::array<int, 3> order :
                 {std::array<int, 3>{0, 1, 2}, {1, 2, 0}, {2, 0, 1}})
                for (int signs = 0; signs < 8; ++signs) {
                    V v{};
                    for (int k = 0; k < 3; ++k) v[order[k]] = base[k] * ((signs >> k & 1) ? -1 : 1);
                    if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
                }
        return out;
    }();
    return list;
}

const std::vector<V>& axisVectors() {
    static const std::vector<V> list = {{0, 0, 100},  {0, 0, -100}, {100, 0, 0},
                                        {-100, 0, 0}, {0, 100, 0},  {0, -100, 0}};
    return list;
}

std::vector<double> asVec(const V& v) {
    return {v[0] / 100.0, v[1] / 100.0, v[2] / 100.0};
}

enum class Case { Diffuse, Both, Behind, Away };

struct PhongData {
    V n{}, l{}, v{};
    int kd = 5, ks = 5, shininess = 1;  // kd, ks in tenths
    int intensity = 2;                  // in halves: 1, 2 or 4 (0.5, 1, 2)
    Case kind = Case::Diffuse;
};

PhongData drawPhong(Random& r, PracticeLevel level) {
    PhongData p;
    if (level == PracticeLevel::Easy) p.kind = Case::Diffuse;
    if (level == PracticeLevel::Medium) p.kind = Case::Both;
    if (level == PracticeLevel::Hard) p.kind = r.chance(50) ? Case::Behind : Case::Away;
    for (;;) {
        // The normal along an axis but at hard, where r = 2 (n.l) n - l takes more work.
        p.n = r.pick(level == PracticeLevel::Hard ? unitVectors() : axisVectors());
        p.l = r.pick(unitVectors());
        p.v = r.pick(unitVectors());
        p.kd = r.between(2, 9);
        p.ks = r.between(2, 8);
        p.shininess = r.between(1, 5);
        p.intensity = r.pick(std::vector<int>{1, 2, 2, 4});
        const long nl = dot4(p.n, p.l), nv = dot4(p.n, p.v);
        // r.v in hundred-millionths: r = 2 (n.l) n - l in millionths.
        V rr{};
        for (int k = 0; k < 3; ++k) rr[k] = 2 * nl * p.n[k] - p.l[k] * 10000;
        const long rv = rr[0] * p.v[0] + rr[1] * p.v[1] + rr[2] * p.v[2];
        // Never grazing (|cos| >= 0.2): a student's picture decides every sign.
        if (std::abs(nl) < 2000 || nv < 2000) continue;
        if (p.kind != Case::Diffuse && std::abs(rv) < 20000000) continue;
        bool fits = false;
        switch (p.kind) {
            case Case::Diffuse:
                fits = nl > 0;
                break;
            case Case::Both: {
                const double spec = p.intensity / 2.0 * p.ks / 10.0 *
                                    std::pow(rv / 1e8, static_cast<double>(p.shininess));
                fits = nl > 0 && rv > 0 && spec >= 0.05;
                break;
            }
            case Case::Behind:
                fits = nl < 0;
                break;
            case Case::Away:
                fits = nl > 0 && rv < 0;
                break;
        }
        if (fits) return p;
    }
}

}  // namespace

Draft makePhong(Random& r, PracticeLevel level) {
    const PhongData p = drawPhong(r, level);
    const bool specular = p.kind != Case::Diffuse;
    const double kd = p.kd / 10.0, ks = p.ks / 10.0, light = p.intensity / 2.0;
    const std::vector<double> n = asVec(p.n), l = asVec(p.l), v = asVec(p.v);

    const auto data = [&](bool it) {
        std::string s = it ? "In un punto colpito la normale unitaria è `n = " + vec(n) +
                                 "`, la direzione unitaria verso la luce `l = " + vec(l) + "`"
                           : "At a hit point the unit normal is `n = " + vec(n) +
                                 "`, the unit direction towards the light `l = " + vec(l) + "`";
        if (specular)
            s += (it ? " e verso l'occhio `v = " : " and towards the eye `v = ") + vec(v) + "`";
        s += it ? "; il materiale ha `k_d = " + num(kd) + "`"
                : "; the material has `k_d = " + num(kd) + "`";
        if (specular)
            s += (it ? ", `k_s = " : ", `k_s = ") + num(ks) + "`" +
                 (it ? " e lucentezza `" : " and shininess `") + std::to_string(p.shininess) + "`";
        s += it ? "; la luce ha intensità `I = " + num(light) + "`."
                : "; the light's intensity is `I = " + num(light) + "`.";
        return s;
    };
    const std::string en = data(false), it = data(true);
    ojson given;
    ojson shading = {{"n", jsonVec(n)}, {"l", jsonVec(l)}};
    if (specular) shading["v"] = jsonVec(v);
    shading["kd"] = kd;
    if (specular) {
        shading["ks"] = ks;
        shading["shininess"] = p.shininess;
    }
    shading["intensity"] = light;
    given["shading"] = shading;
    const auto compute = [&](const std::string& id, const std::string& quantity,
                             const std::string& askEn, const std::string& askIt) {
        return computeExercise(id, quantity, given, text(en + " " + askEn, it + " " + askIt));
    };

    Draft d;
    ojson& lesson = d.lesson;
    lesson["title"] = text("Practice: Phong shading", "Esercitazione: lo shading di Phong");
    std::string modelEn =
        " The slides' local model (Phong): the diffuse term `I_diff = I * k_d * cos(theta)`, "
        "with `cos(theta) = n.l`";
    std::string modelIt =
        " Il modello locale delle slide (Phong): il termine diffuso `I_diff = I * k_d * "
        "cos(theta)`, con `cos(theta) = n.l`";
    if (specular) {
        modelEn +=
            ", and the specular term `I_spec = I * k_s * cos^s(alpha)`, with `s` the shininess "
            "and `cos(alpha) = r.v`, where `r = 2 (n.l) n - l` is the direction to the light "
            "mirrored about the normal";
        modelIt +=
            ", e il termine speculare `I_spec = I * k_s * cos^s(alpha)`, con `s` la lucentezza "
            "e `cos(alpha) = r.v`, dove `r = 2 (n.l) n - l` è la direzione verso la luce "
            "riflessa rispetto alla normale";
    }
    modelEn += ". A negative cosine gives no light: each cosine is taken as `max(0, ...)`.";
    modelIt += ". Un coseno negativo non dà luce: ogni coseno si prende come `max(0, ...)`.";
    const std::string codeEn =
        " raystep's `phong()` (render/shading.h) takes one intensity `I` for both terms, where "
        "the slides write `I_luce diff` and `I_luce spec`, and a finite shininess, where the "
        "slides' perfect mirror has `cos^inf`; with the light behind the surface (`n.l <= 0`) it "
        "gives no highlight either, whatever `r.v`.";
    const std::string codeIt =
        " La `phong()` di raystep (render/shading.h) usa una sola intensità `I` per i due "
        "termini, dove le slide scrivono `I_luce diff` e `I_luce spec`, e una lucentezza finita, "
        "dove lo specchio perfetto delle slide ha `cos^inf`; con la luce dietro la superficie "
        "(`n.l <= 0`) non dà nemmeno il riflesso speculare, qualunque sia `r.v`.";
    lesson["text"] = text(
        en + modelEn + (specular ? codeEn : "") + " Work each answer by hand, then check it.",
        it + modelIt + (specular ? codeIt : "") + " Ricava ogni risposta a mano, poi verificala.");
    // The scene the 3D view shows: a sphere through the hit point with normal n there, the
    // light along l, the eye along v, and the eye's ray to the point.
    const auto along = [&](const std::vector<double>& dir, double k) {
        return jsonVec({k * dir[0], k * dir[1], k * dir[2]});
    };
    const std::vector<double> eyeDir = specular ? v : n;
    ojson scene;
    scene["description"] = "practice: Phong shading at one point of a sphere";
    // The default up, (0, 1, 0), unless the eye looks nearly along it.
    const ojson up =
        std::abs(eyeDir[1]) >= 0.8 ? jsonVec({0.0, 0.0, 1.0}) : jsonVec({0.0, 1.0, 0.0});
    scene["camera"] = {
        {"eye", along(eyeDir, 5.0)}, {"look_at", jsonVec({0.0, 0.0, 0.0})}, {"up", up}};
    scene["lights"] = {{{"position", along(l, 4.0)}, {"intensity", light}}};
    scene["materials"] = {
        {"surface", {{"kd", kd}, {"ks", specular ? ks : 0.0}, {"n", specular ? p.shininess : 1}}}};
    scene["objects"] = {
        {{"type", "sphere"}, {"center", along(n, -1.0)}, {"radius", 1.0}, {"material", "surface"}}};
    lesson["scene"] = scene;
    lesson["setup"] = {{"accel", "bruteforce"}};
    lesson["trace"] = {{"ray", jsonVec({5.0 * eyeDir[0], 5.0 * eyeDir[1], 5.0 * eyeDir[2],
                                        -eyeDir[0], -eyeDir[1], -eyeDir[2]})}};
    lesson["views"] = {"3d"};

    ojson ex = ojson::array();
    ojson nl = compute(
        "n-dot-l", "n.l",
        "Compute `n.l`, the cosine of the angle between the normal and the direction to the light.",
        "Calcola `n.l`, il coseno dell'angolo tra la normale e la direzione verso la luce.");
    nl["hint"] =
        hints({text("`n.l = n.x l.x + n.y l.y + n.z l.z`", "`n.l = n.x l.x + n.y l.y + n.z l.z`")});
    ex.push_back(nl);
    ojson diffuse = compute("diffuse", "diffuse", "Compute the diffuse term `I_diff`.",
                            "Calcola il termine diffuso `I_diff`.");
    diffuse["hint"] =
        hints({text("`I_diff = I * k_d * max(0, n.l)`", "`I_diff = I * k_d * max(0, n.l)`"),
               text("Is the light in front of the surface? The sign of `n.l` says.",
                    "La luce è davanti alla superficie? Lo dice il segno di `n.l`.")});
    ex.push_back(diffuse);
    if (specular) {
        ojson rv = compute("r-dot-v", "r.v",
                           "Compute `r.v`, with `r = 2 (n.l) n - l` the direction to the light "
                           "mirrored about the normal.",
                           "Calcola `r.v`, con `r = 2 (n.l) n - l` la direzione verso la luce "
                           "riflessa rispetto alla normale.");
        rv["hint"] =
            hints({text("First `r`, component by component: `r = 2 (n.l) n - l`; then its dot "
                        "product with `v`.",
                        "Prima `r`, componente per componente: `r = 2 (n.l) n - l`; poi il suo "
                        "prodotto scalare con `v`.")});
        ex.push_back(rv);
        ojson spec =
            compute("specular", "specular",
                    "Compute the specular term `I_spec` as raystep's `phong()` does.",
                    "Calcola il termine speculare `I_spec` come fa la `phong()` di raystep.");
        spec["hint"] =
            hints({text("`I_spec = I * k_s * max(0, r.v)^" + std::to_string(p.shininess) + "`",
                        "`I_spec = I * k_s * max(0, r.v)^" + std::to_string(p.shininess) + "`"),
                   text("Is the light in front of the surface (`n.l > 0`), and does `r` point "
                        "towards the eye (`r.v > 0`)?",
                        "La luce è davanti alla superficie (`n.l > 0`), e `r` punta verso l'occhio "
                        "(`r.v > 0`)?")});
        ex.push_back(spec);
    }
    lesson["exercises"] = ex;

    d.given = {{"n", jsonVec(n)}, {"l", jsonVec(l)}};
    if (specular) d.given["v"] = jsonVec(v);
    d.given["kd"] = kd;
    if (specular) {
        d.given["ks"] = ks;
        d.given["shininess"] = p.shininess;
    }
    d.given["intensity"] = light;
    d.answers = [specular](const Reference& ref) {
        ojson a = {{"nDotL", ref.number("n-dot-l")}, {"diffuse", ref.number("diffuse")}};
        a["rDotV"] = specular ? ojson(ref.number("r-dot-v")) : ojson(nullptr);
        a["specular"] = specular ? ojson(ref.number("specular")) : ojson(nullptr);
        return a;
    };
    return d;
}

}  // namespace raystep::practice

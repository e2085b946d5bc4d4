// Practice on the DDA of Amanatides & Woo, in 2D and 3D: a uniform grid with numbers a student
// works by hand (cells of 1, 0.5 or 2; directions whose reciprocals are short decimals), a ray
// from inside or, from medium on, from outside; at hard, a ray through a grid vertex (a tie).
// The grid's extent is set by two small markers in opposite corners, which the ray misses.
#include "course/practice/generator.h"

#include <algorithm>
#include <cmath>

namespace raystep::practice {

namespace {

constexpr const char* kAxis[] = {"x", "y", "z"};

template <int N>
struct DdaData {
    std::array<int, N> res{};
    std::array<double, N> lo{}, hi{}, o{}, d{};
    double cell = 1.0;
};

/// Coordinates are drawn in whole hundredths and divided once, so 0.9 is the double nearest
/// 0.9 (the one a student types), not 0.1 + 0.8 rounded twice.
double hundredths(long v) {
    return static_cast<double>(v) / 100.0;
}

template <int N>
DdaData<N> drawDda(Random& r, PracticeLevel level) {
    const bool easy = level == PracticeLevel::Easy, hard = level == PracticeLevel::Hard;
    DdaData<N> g;
    // The cell in hundredths: 1, 0.5 or 2.
    long cell = easy ? 100 : r.pick(std::vector<long>{100, 100, 50, 200});
    if (hard) cell = r.pick(std::vector<long>{100, 50});
    g.cell = hundredths(cell);
    // Reciprocals that are short decimals; at hard, exact in binary so a drawn tie is exact.
    const std::vector<double> dirs = hard
                                         ? std::vector<double>{0.25, 0.5, 1.0, 2.0}
                                         : std::vector<double>{0.25, 0.4, 0.5, 0.8, 1.0, 1.25, 2.0};
    // Where in its cell the origin lies, in hundredths of the cell: never on a boundary.
    const std::vector<long> fracs = hard ? std::vector<long>{25, 50, 75}
                                         : std::vector<long>{10, 20, 30, 40, 50, 60, 70, 80, 90};
    std::array<long, N> lo{}, o{};
    for (int a = 0; a < N; ++a) {
        g.res[a] = N == 2 ? r.between(easy ? 3 : 4, easy ? 5 : 6) : r.between(easy ? 2 : 3, 4);
        lo[a] = easy ? 0 : cell * r.between(-2, 2);
        g.d[a] = r.pick(dirs) * (easy ? 1 : r.sign());
        o[a] = lo[a] + cell * r.between(0, g.res[a] - 1) + cell * r.pick(fracs) / 100;
    }
    if (hard) {
        // Through a vertex inside the grid: o = V - s d, with s a multiple of a quarter cell so
        // o stays in whole hundredths.
        const long s = cell * r.pick(std::vector<long>{2, 4, 6, 8, 12}) / 4;
        for (int a = 0; a < N; ++a) {
            const long v = lo[a] + cell * r.between(1, g.res[a] - 1);
            o[a] = v - static_cast<long>(std::lround(static_cast<double>(s) * g.d[a]));
        }
    }
    if (!easy && r.chance(50)) {
        // From outside, through one face: the ray then enters the grid there first.
        const int a = r.between(0, N - 1);
        const long out = cell * r.between(0, 1) + cell * r.pick(fracs) / 100;
        o[a] = g.d[a] > 0 ? lo[a] - out : lo[a] + cell * g.res[a] + out;
    }
    for (int a = 0; a < N; ++a) {
        g.lo[a] = hundredths(lo[a]);
        g.hi[a] = hundredths(lo[a] + cell * g.res[a]);
        g.o[a] = hundredths(o[a]);
    }
    return g;
}

std::vector<double> asVec(const auto& a) {
    return std::vector<double>(a.begin(), a.end());
}

template <int N>
std::string gridWords(const DdaData<N>& g, bool it) {
    std::string cells, size;
    for (int a = 0; a < N; ++a) {
        cells += (a ? " x " : "") + std::to_string(g.res[a]);
        size += (a ? " x " : "") + num(g.cell, it);
    }
    const std::string box = "`min = " + vec(asVec(g.lo)) + "`" + (it ? " a " : " to ") +
                            "`max = " + vec(asVec(g.hi)) + "`";
    const std::string ray = "`o = " + vec(asVec(g.o)) + "`, `d = " + vec(asVec(g.d)) + "`";
    if (it)
        return "Il raggio " + ray + " e una griglia uniforme di " + cells + " celle da " + box +
               ", celle di " + size + ".";
    return "The ray " + ray + " and a uniform grid of " + cells + " cells from " + box +
           ", cells of " + size + ".";
}

template <int N>
ojson markers(const DdaData<N>& g) {
    // Two markers whose bounds are the grid's corners, exactly (cell / 8 is exact in binary).
    const double rad = g.cell / 8;
    std::array<double, N> a{}, b{};
    for (int k = 0; k < N; ++k) {
        a[k] = g.lo[k] + rad;
        b[k] = g.hi[k] - rad;
    }
    ojson scene;
    if constexpr (N == 2) {
        scene["dimensions"] = 2;
        scene["description"] = "practice: a uniform grid marked by two corner circles";
        scene["grid"] = {g.res[0], g.res[1]};
        scene["circles"] = {{{"center", jsonVec(asVec(a))}, {"radius", rad}},
                            {{"center", jsonVec(asVec(b))}, {"radius", rad}}};
    } else {
        std::array<double, 3> c{}, e{};
        double extent = 0;
        for (int k = 0; k < 3; ++k) {
            c[k] = (g.lo[k] + g.hi[k]) / 2;
            extent = std::max(extent, g.hi[k] - g.lo[k]);
        }
        e = {c[0] + 1.3 * extent, c[1] + 1.0 * extent, c[2] + 2.0 * extent};
        scene["description"] = "practice: a uniform grid marked by two corner spheres";
        scene["camera"] = {{"eye", jsonVec(asVec(e))}, {"look_at", jsonVec(asVec(c))}};
        scene["lights"] = {{{"position", jsonVec(asVec(e))}}};
        scene["objects"] = {{{"type", "sphere"}, {"center", jsonVec(asVec(a))}, {"radius", rad}},
                            {{"type", "sphere"}, {"center", jsonVec(asVec(b))}, {"radius", rad}}};
    }
    return scene;
}

/// The walk starts off every grid line: the origin (inside) or the entry point (from outside),
/// but at hard, where a ray may come in through a vertex.
template <int N>
bool startFits(const DdaData<N>& g, PracticeLevel level) {
    double tEnter = 0.0;
    for (int a = 0; a < N; ++a) {
        const double t = ((g.d[a] > 0 ? g.lo[a] : g.hi[a]) - g.o[a]) / g.d[a];
        tEnter = std::max(tEnter, t);
    }
    for (int a = 0; a < N; ++a) {
        const double p = g.o[a] + tEnter * g.d[a];
        const double along = (p - g.lo[a]) / g.cell;
        const bool entryAxis = tEnter > 0 && std::abs(along - std::round(along)) < 1e-9 &&
                               (std::round(along) == 0 || std::round(along) == g.res[a]);
        if (entryAxis) continue;
        if (std::abs(along - std::round(along)) < 0.05 &&
            (tEnter == 0 || level != PracticeLevel::Hard))
            return false;
    }
    return true;
}

/// The walk is one for its level: inside the hand's reach, no near tie a student's rounding
/// could decide either way, and at hard at least one exact tie (cells stepped on two axes).
template <int N>
bool walkFits(const Reference& ref, PracticeLevel level) {
    const EventLog& log = ref.log();
    int cells = 0, ties = 0;
    double tEnter = 0;
    for (const Event& e : log.events()) {
        if (std::holds_alternative<RayHit>(e)) return false;  // a corner marker
        if (const auto* s = std::get_if<DdaSetup>(&e)) tEnter = s->tEnter;
        const auto* c = std::get_if<DdaCell>(&e);
        if (!c) continue;
        ++cells;
        if (std::popcount(static_cast<unsigned>(c->axes)) > 1 && cells > 1) ++ties;
        if (cells == 1 && std::popcount(static_cast<unsigned>(c->axes)) > 1) return false;
        std::array<double, N> t{};
        for (int a = 0; a < N; ++a) t[a] = c->tMax[a];
        std::sort(t.begin(), t.end());
        const double gap = t[1] - t[0];
        if (gap != 0.0 && gap < 0.05) return false;
        if (gap == 0.0 && level != PracticeLevel::Hard) return false;
        if (cells == 1 && t[0] - tEnter < 0.05) return false;  // entered next to a boundary
    }
    const int most = level == PracticeLevel::Easy ? 6 : level == PracticeLevel::Medium ? 8 : 9;
    if (cells < 3 || cells > most) return false;
    return level != PracticeLevel::Hard || ties > 0;
}

template <int N>
Draft makeDda(Random& r, PracticeLevel level) {
    DdaData<N> g = drawDda<N>(r, level);
    // Every axis at one speed makes every tDelta one number and every step a tie: draw again.
    const auto sameSpeed = [&] {
        for (int a = 1; a < N; ++a)
            if (std::abs(g.d[a]) != std::abs(g.d[0])) return false;
        return true;
    };
    while (sameSpeed() || !startFits(g, level)) g = drawDda<N>(r, level);
    const std::string en = gridWords(g, false), it = gridWords(g, true);
    const std::string dims = N == 2 ? "X,Y" : "X,Y,Z";
    Draft d;
    ojson& l = d.lesson;
    l["title"] = text("Practice: the " + std::to_string(N) + "D DDA",
                      "Esercitazione: il DDA in " + std::to_string(N) + "D");
    l["text"] =
        text(en + " The two small " + (N == 2 ? "circles" : "spheres") +
                 " only mark the grid's corners; the ray misses them. Work each answer by hand "
                 "from these numbers, then check it.",
             it + (N == 2 ? " I due piccoli cerchi" : " Le due piccole sfere") +
                 " segnano solo gli angoli della griglia; il raggio non li tocca. Ricava ogni "
                 "risposta a mano da questi numeri, poi verificala.");
    l["scene"] = markers(g);
    ojson setup = {{"accel", "grid"}, {"mailbox", true}};
    setup["grid_res"] = ojson::array();
    for (int a = 0; a < N; ++a) setup["grid_res"].push_back(g.res[a]);
    l["setup"] = setup;
    ojson ray = ojson::array();
    for (int a = 0; a < N; ++a) ray.push_back(g.o[a]);
    for (int a = 0; a < N; ++a) ray.push_back(g.d[a]);
    l["trace"] = {{"ray", ray}};
    if (N == 3) l["views"] = {"3d"};
    ojson given;
    given["ray"] = {{"o", jsonVec(asVec(g.o))}, {"d", jsonVec(asVec(g.d))}};
    ojson cellSize = ojson::array(), res = ojson::array();
    for (int a = 0; a < N; ++a) {
        cellSize.push_back(g.cell);
        res.push_back(g.res[a]);
    }
    given["grid"] = {{"min", jsonVec(asVec(g.lo))}, {"cell", cellSize}, {"res", res}};
    ojson ex = ojson::array();
    ojson first = exercise(
        "first-cell", "next_cell",
        text("Which cell is the ray in first (" + dims +
                 ", counted from 0 at min)? A ray from outside starts where it enters the grid.",
             "In quale cella si trova per prima il raggio (" + dims +
                 ", contate da 0 a partire da min)? Un raggio da fuori parte da dove entra "
                 "nella griglia."));
    first["hint"] =
        hints({text("cell = floor((point - min) / cell size), axis by axis, at the "
                    "point where the walk starts.",
                    "cella = floor((punto - min) / lato della cella), asse per asse, "
                    "nel punto in cui il cammino comincia.")});
    ex.push_back(first);
    for (int a = 0; a < N; ++a) {
        ojson e = exercise(
            "tdelta-" + std::string(kAxis[a]), "value",
            text(en + " Compute tDelta." + kAxis[a] +
                     ": how far t goes while the ray crosses one cell in " + kAxis[a] + ".",
                 it + " Calcola tDelta." + kAxis[a] +
                     ": di quanto cresce t mentre il raggio attraversa una cella "
                     "in " +
                     kAxis[a] + "."));
        e["type"] = "compute";
        e["given"] = given;
        e["quantity"] = "tDelta." + std::string(kAxis[a]);
        e["hint"] =
            hints({text("A cell is " + num(g.cell) + " wide; the ray moves |d." + kAxis[a] +
                            "| per unit of t.",
                        "Una cella è larga " + num(g.cell, true) + "; il raggio avanza di |d." +
                            kAxis[a] + "| per unità di t."),
                   text(std::string("tDelta.") + kAxis[a] + " = cell / |d." + kAxis[a] + "|",
                        std::string("tDelta.") + kAxis[a] + " = cella / |d." + kAxis[a] + "|")});
        ex.push_back(e);
    }
    for (int a = 0; a < N; ++a) {
        ojson e = exercise(
            "tmax-" + std::string(kAxis[a]), "value",
            text(en + " At the set-up, in the first cell the ray is in: compute tMax." + kAxis[a] +
                     ", the t where it crosses the next boundary in " + kAxis[a] + ".",
                 it +
                     " All'inizializzazione, nella prima cella in cui si trova il raggio: "
                     "calcola tMax." +
                     kAxis[a] + ", il t in cui attraversa il prossimo bordo in " + kAxis[a] + "."));
        e["type"] = "compute";
        e["given"] = given;
        e["quantity"] = "tMax." + std::string(kAxis[a]);
        e["hint"] =
            hints({text("Which boundary of the first cell lies ahead in " + std::string(kAxis[a]) +
                            "? It depends on the sign of d." + kAxis[a] + ".",
                        "Quale bordo della prima cella sta davanti in " + std::string(kAxis[a]) +
                            "? Dipende dal segno di d." + kAxis[a] + "."),
                   text(std::string("tMax.") + kAxis[a] + " = (boundary - o." + kAxis[a] +
                            ") / d." + kAxis[a],
                        std::string("tMax.") + kAxis[a] + " = (bordo - o." + kAxis[a] + ") / d." +
                            kAxis[a])});
        ex.push_back(e);
    }
    ojson next = exercise(
        "next-cell", "next_cell",
        text("The ray is in its first cell. Which cell does the DDA enter next (" + dims + ")?",
             "Il raggio è nella sua prima cella. In quale cella entra poi il DDA (" + dims + ")?"));
    next["at"] = {{"after", "dda_cell"}};
    next["hint"] = hints({text("The DDA steps along the axis whose tMax is smallest.",
                               "Il DDA avanza lungo l'asse con il tMax più piccolo.")});
    ex.push_back(next);
    ojson walk = exercise(
        "walk", "sequence",
        text("Give every cell the ray visits, in order, until it leaves the grid (" + dims +
                 "; separate cells with ';').",
             "Scrivi ogni cella che il raggio visita, in ordine, finché esce dalla griglia (" +
                 dims + "; separa le celle con ';')."));
    walk["of"] = "dda_cell";
    walk["hint"] =
        hints({text("Step by step: take the smallest tMax, move one cell along its "
                    "axis, add tDelta to it. Equal tMax: step both axes at once.",
                    "Passo per passo: prendi il tMax più piccolo, avanza di una cella "
                    "sul suo asse, aggiungigli tDelta. tMax uguali: avanza su entrambi "
                    "gli assi insieme.")});
    ex.push_back(walk);
    l["exercises"] = ex;

    ojson gridRes = ojson::array();
    for (int a = 0; a < N; ++a) gridRes.push_back(g.res[a]);
    d.given = {{"grid", gridRes},
               {"min", jsonVec(asVec(g.lo))},
               {"max", jsonVec(asVec(g.hi))},
               {"origin", jsonVec(asVec(g.o))},
               {"dir", jsonVec(asVec(g.d))}};
    d.answers = [](const Reference& ref) {
        ojson tDelta = ojson::array(), tMax = ojson::array();
        for (int a = 0; a < N; ++a) {
            tDelta.push_back(ref.number("tdelta-" + std::string(kAxis[a])));
            tMax.push_back(ref.number("tmax-" + std::string(kAxis[a])));
        }
        return ojson{{"tDelta", tDelta},
                     {"tMax", tMax},
                     {"firstCell", ref.cell("first-cell")},
                     {"nextCell", ref.cell("next-cell")},
                     {"walk", ref.cells("walk")}};
    };
    d.accept = [level](const Reference& ref) { return walkFits<N>(ref, level); };
    return d;
}

}  // namespace

Draft makeDda2D(Random& random, PracticeLevel level) {
    return makeDda<2>(random, level);
}
Draft makeDda3D(Random& random, PracticeLevel level) {
    return makeDda<3>(random, level);
}

}  // namespace raystep::practice

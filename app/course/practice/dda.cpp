// Practice on the DDA of Amanatides & Woo, in 2D and 3D: a uniform grid with numbers a student
// works by hand (cells of 1, 0.5 or 2; directions whose reciprocals are short decimals), a ray
// from inside or, from medium on, from outside; at hard, a ray through a grid vertex (a tie).
// The grid's extent is set by two small markers in opposite corners, which the ray misses.
#include "course/practice/grid_draw.h"

namespace raystep::practice {

namespace {

constexpr const char* kAxis[] = {"x", "y", "z"};

/// The walk is one for its level: inside the hand's reach, no near tie a student's rounding
/// could decide either way, and at hard at least one exact tie (cells stepped on two axes).
template <int N>
bool walkFits(const Reference& ref, PracticeLevel level) {
    const WalkShape w = walkShape<N>(ref.log(), level == PracticeLevel::Hard);
    if (w.hit || !w.readable) return false;  // a hit is a corner marker
    const int most = level == PracticeLevel::Easy ? 6 : level == PracticeLevel::Medium ? 8 : 9;
    if (w.cells < 3 || w.cells > most) return false;
    return level != PracticeLevel::Hard || w.ties > 0;
}

template <int N>
Draft makeDda(Random& r, PracticeLevel level) {
    DdaData<N> g = drawDda<N>(r, level);
    while (oneSpeed(g) || !startFits(g, level)) g = drawDda<N>(r, level);
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
             "Qual è la prima cella in cui si trova il raggio (" + dims +
                 ", indici contati da 0 a partire da min)? Per un raggio esterno, la prima cella "
                 "è quella in cui entra nella griglia."));
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

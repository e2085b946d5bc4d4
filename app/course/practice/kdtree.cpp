// Practice on building and walking a kd-tree (lessons 10 and 11): P(L|C) and P(R|C) of a named
// plane (in 2D the ratio of perimeters, as the engine's compute and lesson 11 take it), its SAH
// cost, the cheapest of three candidates, and the nodes TestTree enters on the tree raystep
// builds. easy: one plane of the root, both sides full; medium: + three candidates + TestTree;
// hard: the plane in a child of the root, cutting off empty space (the empty bonus), + the rest.
#include "course/practice/tree2d.h"

#include "course/compute.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace raystep::practice {

namespace {

using namespace tree2d;

constexpr const char* kAxis[] = {"x", "y"};

// The lesson's costs, lesson 11's and raystep's defaults (pbrt-v4's).
constexpr double kCTrav = 1.0, kCIsect = 5.0, kEmptyBonus = 0.5;

struct Plane {
    int axis = 0;
    double at = 0.0;
    int nl = 0, nr = 0;
};

/// The primitives of a node: those whose bounds lie in its box (a straddling one is refused
/// before: its clipped bounds would be no short decimals).
std::vector<BoxN<2>> boundsIn(const Scene2D& s, const BoxN<2>& box) {
    std::vector<BoxN<2>> out;
    for (std::uint32_t p = 0; p < s.primitiveCount(); ++p) {
        const BoxN<2> b = s.primitiveBounds(p);
        if (b.lo[0] >= box.lo[0] && b.hi[0] <= box.hi[0] && b.lo[1] >= box.lo[1] &&
            b.hi[1] <= box.hi[1])
            out.push_back(b);
    }
    return out;
}

/// Planes on the half-unit lattice strictly inside the node, none on a primitive's bound (where
/// a student could not tell on which side the primitive counts).
std::vector<Plane> planesOf(const std::vector<BoxN<2>>& prims, const BoxN<2>& box) {
    std::vector<Plane> out;
    for (int a = 0; a < 2; ++a)
        for (int h = static_cast<int>(std::lround(box.lo[a] * 2)) + 1; halves(h) < box.hi[a]; ++h) {
            Plane p{a, halves(h)};
            bool onBound = false;
            for (const BoxN<2>& b : prims) {
                onBound = onBound || b.lo[a] == p.at || b.hi[a] == p.at;
                p.nl += b.lo[a] < p.at;
                p.nr += b.hi[a] > p.at;
            }
            if (!onBound) out.push_back(p);
        }
    return out;
}

/// The plane's SAH cost as the lesson's compute exercise takes it (course/compute.cpp, with the
/// kernel accel/sah.h): the choice's answer is the engine's, not this file's arithmetic.
double engineCost(const BoxN<2>& box, const Plane& p) {
    Exercise ex;
    ex.id = "cost";
    ex.kind = ExerciseKind::Compute;
    ex.computeQuantity = "sahCost";
    ComputeGiven& g = ex.given;
    g.shape = ComputeGiven::Shape::Node;
    g.dims = 2;
    g.lo = {box.lo[0], box.lo[1], 0.0};
    g.hi = {box.hi[0], box.hi[1], 0.0};
    g.axis = p.axis;
    g.at = p.at;
    g.nl = p.nl;
    g.nr = p.nr;
    g.cTrav = kCTrav;
    g.cIsect = kCIsect;
    g.emptyBonus = kEmptyBonus;
    return computeAnswer(ex, "practice");
}

std::string planeText(const Plane& p, bool it) {
    return std::string(kAxis[p.axis]) + " = " + num(p.at, it);
}

std::string joinAnd(const std::vector<std::string>& items, bool it) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i)
        out += (i == 0 ? "" : i + 1 == items.size() ? (it ? " e " : " and ") : ", ") + items[i];
    return out;
}

std::string lowerFirst(std::string s) {
    if (!s.empty()) s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
    return s;
}

/// "node 0: the plane x = 3, children 1 (x < 3) and 4 (x > 3); leaf 1: circle 0; ...".
std::string treeWords(const Scene2D& s, const std::vector<TreeNode>& nodes, bool it) {
    std::vector<std::string> parts;
    for (const TreeNode& n : nodes) {
        const std::string id = std::to_string(n.id);
        if (!n.leaf) {
            const std::string a = kAxis[n.axis], at = num(n.split, it);
            parts.push_back((it ? "nodo " : "node ") + id +
                            (it ? ": il piano `" : ": the plane `") + a + " = " + num(n.split) +
                            (it ? "`, figli " : "`, children ") + std::to_string(n.left) + " (" +
                            a + " < " + at + ")" + (it ? " e " : " and ") +
                            std::to_string(n.right) + " (" + a + " > " + at + ")");
            continue;
        }
        std::vector<std::string> names;
        for (std::uint32_t p : n.prims) names.push_back(primName(s, p, it));
        parts.push_back((it ? "foglia " : "leaf ") + id + ": " +
                        (names.empty() ? std::string(it ? "vuota" : "empty") : joinAnd(names, it)));
    }
    std::string out;
    for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? "; " : "") + parts[i];
    return out;
}

/// Everything one instance holds, drawn again until it fits its level.
struct KdData {
    Scene2D scene;
    std::vector<TreeNode> nodes;
    BoxN<2> root, box;  // the tree's root box; the node of the named plane
    std::uint32_t node = 0;
    Plane plane;
    std::vector<Plane> candidates;
    int cheapest = 0;
    Ray2 ray;
};

std::optional<KdData> drawKd(Random& r, PracticeLevel level) {
    const bool easy = level == PracticeLevel::Easy, hard = level == PracticeLevel::Hard;
    KdData g;
    g.scene =
        drawPrims(r, easy ? r.between(3, 4) : r.between(4, 5), r.between(6, 8), r.between(4, 6));
    AccelOptions options;
    options.kdtree.split = SplitMethod::Sah;
    options.kdtree.cTrav = kCTrav;
    options.kdtree.cIsect = kCIsect;
    options.kdtree.emptyBonus = kEmptyBonus;
    g.nodes = treeNodes(g.scene, AccelKind::KdTree, options);
    g.root = g.nodes.front().box;
    if (g.nodes.size() < 3 || g.nodes.size() > (easy ? 99u : 11u)) return std::nullopt;

    g.box = g.root;
    if (hard) {
        // A child of the root whose primitives all lie on its side: it has a strip of empty
        // space to cut off, and its primitives' bounds are their own.
        const TreeNode& root = g.nodes[0];
        const auto [left, right] = g.root.splitAt(root.axis, root.split);
        for (std::uint32_t p = 0; p < g.scene.primitiveCount(); ++p) {
            const BoxN<2> b = g.scene.primitiveBounds(p);
            if (b.lo[root.axis] < root.split && b.hi[root.axis] > root.split) return std::nullopt;
        }
        const bool goLeft = r.chance(50);
        g.node = goLeft ? root.left : root.right;
        g.box = goLeft ? left : right;
    }
    const std::vector<BoxN<2>> prims = boundsIn(g.scene, g.box);
    if (prims.size() < 2) return std::nullopt;
    std::vector<Plane> named, others;
    for (const Plane& p : planesOf(prims, g.box)) {
        const bool emptySide = p.nl == 0 || p.nr == 0;
        (emptySide == hard ? named : others).push_back(p);
    }
    if (named.empty()) return std::nullopt;
    g.plane = r.pick(named);
    if (easy) return g;

    // Three candidates besides the named plane, costs apart enough to rank by hand.
    std::vector<Plane> pool = others;
    for (const Plane& p : named)
        if (p.axis != g.plane.axis || p.at != g.plane.at) pool.push_back(p);
    if (pool.size() < 3) return std::nullopt;
    std::vector<double> costs;
    for (int k = 0; k < 3; ++k) {
        const std::size_t i = static_cast<std::size_t>(r.between(0, int(pool.size()) - 1));
        g.candidates.push_back(pool[i]);
        costs.push_back(engineCost(g.box, pool[i]));
        pool.erase(pool.begin() + static_cast<long>(i));
    }
    for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 3; ++b)
            if (std::abs(costs[a] - costs[b]) < 0.15) return std::nullopt;
    g.cheapest = static_cast<int>(std::min_element(costs.begin(), costs.end()) - costs.begin());

    // The ray for TestTree, clear of every line the tree draws.
    const auto ray = clearRay(r, g.scene, g.root, g.nodes);
    if (!ray) return std::nullopt;
    g.ray = *ray;
    return g;
}

}  // namespace

Draft makeKdTree(Random& r, PracticeLevel level) {
    const bool easy = level == PracticeLevel::Easy, hard = level == PracticeLevel::Hard;
    std::optional<KdData> drawn;
    // A draw fails a rule now and then; thousands in a row would be a bug, not bad luck.
    for (int draws = 0; !(drawn = drawKd(r, level)); ++draws)
        if (draws > 100000) throw std::logic_error("practice: no draw fits the level");
    const KdData& g = *drawn;
    const BoxN<2>& box = g.box;

    // The scene and, at hard, the node: the words every prompt starts from.
    const auto sceneWords = [&](bool it) {
        const std::string list = primList(g.scene, it);
        if (it)
            return "Le primitive: " + list + ". Il kd-tree parte dalla scatola che le contiene, " +
                   corners(g.root, true) + ".";
        return "The primitives: " + list + ". The kd-tree starts from the box that bounds them, " +
               corners(g.root, false) + ".";
    };
    const auto nodeWords = [&](bool it) {
        const std::size_t held = boundsIn(g.scene, box).size();
        if (!hard)
            return std::string(it ? "La radice C, " : "The root C, ") + corners(box, it) +
                   (it ? ", con tutte le " : ", with all ") + std::to_string(held) +
                   (it ? " primitive" : " primitives");
        const TreeNode& root = g.nodes[0];
        const bool left = g.node == root.left;
        const std::string a = kAxis[root.axis], at = num(root.split, it);
        const std::string side = a + (left ? " < " : " > ") + at;
        if (it)
            return "Il nodo C = " + std::to_string(g.node) +
                   ", il figlio della radice dalla parte " + side + ", " + corners(box, true) +
                   ", con " + std::to_string(held) +
                   " primitive (nessuna attraversa il piano della radice)";
        return "The node C = " + std::to_string(g.node) + ", the root's child on the side " + side +
               ", " + corners(box, false) + ", holding " + std::to_string(held) +
               " primitives (none crosses the root's plane)";
    };
    // "with N_L = 2 primitives on the left and N_R = 3 on the right" (below / above for y).
    const auto planeWords = [&](const Plane& p, bool it) {
        const bool x = p.axis == 0;
        const std::string lo =
            it ? (x ? " a sinistra" : " sotto") : (x ? " on the left" : " below");
        const std::string hi = it ? (x ? " a destra" : " sopra") : (x ? " on the right" : " above");
        return (it ? "dal piano `" : "the plane `") + std::string(kAxis[p.axis]) + " = " +
               num(p.at) + "`" + (it ? ", con N_L = " : ", with N_L = ") + std::to_string(p.nl) +
               (it ? " primitive" : " primitives") + lo + (it ? " e N_R = " : " and N_R = ") +
               std::to_string(p.nr) + hi;
    };
    const std::string costs = "C_trav = " + num(kCTrav) + ", C_isect = " + num(kCIsect);
    const std::string bonusEn = "empty bonus " + num(kEmptyBonus);
    const std::string bonusIt = "bonus per lo spazio vuoto " + num(kEmptyBonus, true);
    const std::string leadEn = nodeWords(false) + ", is cut by " + planeWords(g.plane, false) +
                               " (a primitive that crosses the plane counts on both sides).";
    // "La radice ... è tagliata", "Il nodo ... è tagliato".
    const std::string leadIt = nodeWords(true) + (hard ? ", è tagliato " : ", è tagliata ") +
                               planeWords(g.plane, true) +
                               " (una primitiva che attraversa il piano conta da entrambe le "
                               "parti).";

    Draft d;
    ojson& l = d.lesson;
    l["title"] = text("Practice: building a kd-tree with the SAH",
                      "Esercitazione: costruire un kd-tree con la SAH");
    l["text"] = text(
        sceneWords(false) +
            " A cell's \"area\" in 2D is its perimeter, as in lesson 11: `P(L|C) = perimeter(L) / "
            "perimeter(C)`, and the SAH cost is `C_trav + C_isect (P(L|C) N_L + P(R|C) N_R)`, "
            "times `(1 - b)` when a side is empty (b the empty bonus). Here " +
            costs + ", " + bonusEn + ". Work each answer by hand, then check it.",
        sceneWords(true) +
            " In 2D l'\"area\" di una cella è il suo perimetro, come nella lezione 11: `P(L|C) = "
            "perimetro(L) / perimetro(C)`, e il costo SAH è `C_trav + C_isect (P(L|C) N_L + "
            "P(R|C) N_R)`, per `(1 - b)` se una delle due parti è vuota (b il bonus per lo "
            "spazio vuoto). Qui " +
            costs + ", " + bonusIt + ". Ricava ogni risposta a mano, poi verificala.");
    l["scene"] = sceneJson(g.scene, "practice: a few circles and segments for a kd-tree");
    l["setup"] = {{"accel", "kdtree"},
                  {"split", "sah"},
                  {"c_trav", kCTrav},
                  {"c_isect", kCIsect},
                  {"empty_bonus", kEmptyBonus}};
    l["views"] = {"2d"};
    // easy asks no walk: its replay is the build, as lesson 11's, and its figure draws no ray.
    if (easy)
        l["trace"] = {{"build", true}};
    else
        l["trace"] = {{"ray", jsonVec({g.ray.origin.x, g.ray.origin.y, g.ray.dir.x, g.ray.dir.y})}};

    ojson computeGiven = {{"node", boxJson(box)},
                          {"plane", {{"axis", kAxis[g.plane.axis]}, {"at", g.plane.at}}},
                          {"nl", g.plane.nl},
                          {"nr", g.plane.nr}};
    const std::string sideEn = g.plane.axis == 0 ? "left" : "lower";
    const std::string sideIt = g.plane.axis == 0 ? "sinistra" : "inferiore";
    ojson ex = ojson::array();
    const auto compute = [&](const std::string& id, const std::string& quantity,
                             const std::string& askEn, const std::string& askIt) {
        return computeExercise(id, quantity, computeGiven,
                               text(leadEn + " " + askEn, leadIt + " " + askIt));
    };
    ojson pl = compute(
        "p-left", "pL",
        "Compute P(L|C), the probability that a ray crossing C crosses its " + sideEn +
            " part L (in 2D: the ratio of the perimeters).",
        "Calcola P(L|C), la probabilità che un raggio che attraversa C attraversi la sua parte " +
            sideIt + " L (in 2D: il rapporto dei perimetri).");
    pl["hint"] =
        hints({text("perimeter = 2 (width + height); L is the part of C where " +
                        std::string(kAxis[g.plane.axis]) + " < " + num(g.plane.at) + ".",
                    "perimetro = 2 (larghezza + altezza); L è la parte di C in cui " +
                        std::string(kAxis[g.plane.axis]) + " < " + num(g.plane.at, true) + "."),
               text("The counts of primitives play no part in P(L|C).",
                    "Il numero di primitive non entra in P(L|C).")});
    ex.push_back(pl);
    ojson pr = compute("p-right", "pR",
                       "Compute P(R|C), for the other part R (in 2D: the ratio of the perimeters).",
                       "Calcola P(R|C), per l'altra parte R (in 2D: il rapporto dei perimetri).");
    pr["hint"] = hints({text("P(L|C) + P(R|C) is more than 1: both parts share the cut's edge.",
                             "P(L|C) + P(R|C) supera 1: le due parti hanno in comune il lato del "
                             "taglio.")});
    ex.push_back(pr);
    ojson cost = compute("cost", "sahCost", "Its SAH cost, with " + costs + " and " + bonusEn + "?",
                         "Il suo costo SAH, con " + costs + " e " + bonusIt + "?");
    cost["hint"] =
        hints({text(hard ? "One side holds no primitive: the bonus applies."
                         : "Neither side is empty, so the bonus does not apply.",
                    hard ? "Una delle due parti non contiene primitive: il bonus si applica."
                         : "Nessuna delle due parti è vuota, quindi il bonus non si applica."),
               text("Cost = C_trav + C_isect (P(L|C) N_L + P(R|C) N_R)" +
                        std::string(hard ? ", times (1 - b)." : "."),
                    "Costo = C_trav + C_isect (P(L|C) N_L + P(R|C) N_R)" +
                        std::string(hard ? ", per (1 - b)." : "."))});
    ex.push_back(cost);

    if (!easy) {
        // The planes in the prompt too: a printed sheet lists no options.
        std::vector<std::string> planes;
        for (const Plane& p : g.candidates)
            planes.push_back("`" + std::string(kAxis[p.axis]) + " = " + num(p.at) + "` (N_L = " +
                             std::to_string(p.nl) + ", N_R = " + std::to_string(p.nr) + ")");
        ojson ch = exercise("cheapest", "choice",
                            text("Take " + lowerFirst(nodeWords(false)) + ": which of the planes " +
                                     joinAnd(planes, false) + " has the lowest SAH cost (" + costs +
                                     ", " + bonusEn + ")?",
                                 "Considera " + lowerFirst(nodeWords(true)) + ": quale dei piani " +
                                     joinAnd(planes, true) + " ha il costo SAH minore (" + costs +
                                     ", " + bonusIt + ")?"));
        ojson choices = ojson::array();
        for (std::size_t k = 0; k < g.candidates.size(); ++k) {
            const Plane& p = g.candidates[k];
            const bool best = static_cast<int>(k) == g.cheapest;
            const std::string counts =
                " (N_L = " + std::to_string(p.nl) + ", N_R = " + std::to_string(p.nr) + ")";
            const bool empty = p.nl == 0 || p.nr == 0;
            choices.push_back(
                {{"text",
                  text("`" + planeText(p, false) + "`" + counts,
                       "`" + std::string(kAxis[p.axis]) + " = " + num(p.at) + "`" + counts)},
                 {"why",
                  best ? text("The cheapest of the three: its parts' perimeters, weighted by their "
                              "counts, add up to the least" +
                                  std::string(empty ? ", and the empty side halves it." : "."),
                              "Il meno costoso dei tre: i perimetri delle sue parti, pesati con i "
                              "loro conteggi, danno la somma minore" +
                                  std::string(empty ? ", e la parte vuota la dimezza." : "."))
                       : text("It costs more than the cheapest of the three" +
                                  std::string(empty ? ", even with the empty bonus." : "."),
                              "Costa più del meno costoso dei tre" +
                                  std::string(empty ? ", anche con il bonus per lo spazio vuoto."
                                                    : "."))}});
        }
        ch["choices"] = choices;
        ch["answer"] = g.cheapest;
        ch["hint"] = hints(
            {text("Work out each plane's cost as above: P by the perimeters of its two parts.",
                  "Calcola il costo di ogni piano come sopra: le P con i perimetri delle sue due "
                  "parti."),
             text("A plane with an empty side gets the bonus: its cost is multiplied by (1 - b).",
                  "Un piano con una parte vuota riceve il bonus: il suo costo va moltiplicato per "
                  "(1 - b).")});
        ex.push_back(ch);

        const auto rayText = [&](bool it) {
            return (it ? "parte da `o = " : "starts at `o = ") +
                   vec({g.ray.origin.x, g.ray.origin.y}) +
                   (it ? "` con direzione `d = " : "` with direction `d = ") +
                   vec({g.ray.dir.x, g.ray.dir.y}) + "`";
        };
        ojson seq = exercise(
            "test-tree", "sequence",
            text(
                "The kd-tree raystep builds on these primitives with the SAH (" + costs + ", " +
                    bonusEn + "): " + treeWords(g.scene, g.nodes, false) + ". The ray " +
                    rayText(false) +
                    ". Which nodes does TestTree enter, in order (node ids separated by "
                    "spaces)? As raystep runs it (lesson 10): the slab test at the root gives "
                    "[tNear, tFar]; the child on the origin's side first, the other on the "
                    "stack with its part of the interval; a child the ray does not reach "
                    "within [tNear, tFar] is not entered; the walk stops when the nearest hit "
                    "found lies before the next node's tNear.",
                "Il kd-tree che raystep costruisce su queste primitive con la SAH (" + costs +
                    ", " + bonusIt + "): " + treeWords(g.scene, g.nodes, true) + ". Il raggio " +
                    rayText(true) +
                    ". In quali nodi entra TestTree, in ordine (gli id dei nodi separati da "
                    "spazi)? Come lo esegue raystep (lezione 10): il test degli slab nella "
                    "radice dà [tNear, tFar]; prima il figlio dalla parte dell'origine, l'altro "
                    "sulla pila con la sua parte dell'intervallo; in un figlio che il raggio non "
                    "raggiunge dentro [tNear, tFar] non si entra; la visita si ferma quando "
                    "l'intersezione più vicina trovata cade prima del tNear del nodo successivo."));
        seq["of"] = "node_enter";
        seq["hint"] = hints(
            {text("The ray crosses the plane x = X at t = (X - o.x) / d.x, y = Y at t = (Y - "
                  "o.y) / d.y: that t splits a node's [tNear, tFar] between its children.",
                  "Il raggio attraversa il piano x = X a t = (X - o.x) / d.x, y = Y a t = (Y - "
                  "o.y) / d.y: quel t divide l'intervallo [tNear, tFar] di un nodo tra i suoi "
                  "figli."),
             text("In a leaf, test its primitives: a hit before the next node's tNear ends the "
                  "walk.",
                  "In una foglia, testa le sue primitive: un'intersezione prima del tNear del "
                  "nodo successivo conclude la visita.")});
        ex.push_back(seq);
    }
    l["exercises"] = ex;

    ojson given;
    given["min"] = jsonVec({box.lo[0], box.lo[1]});
    given["max"] = jsonVec({box.hi[0], box.hi[1]});
    given["node"] = g.node;
    given["axis"] = kAxis[g.plane.axis];
    given["position"] = g.plane.at;
    given["nl"] = g.plane.nl;
    given["nr"] = g.plane.nr;
    given["cTrav"] = kCTrav;
    given["cIsect"] = kCIsect;
    given["emptyBonus"] = kEmptyBonus;
    addPrims(given, g.scene);
    given["root"] = boxJson(g.root);
    if (!easy) {
        ojson cands = ojson::array();
        for (const Plane& p : g.candidates)
            cands.push_back(
                {{"axis", kAxis[p.axis]}, {"position", p.at}, {"nl", p.nl}, {"nr", p.nr}});
        given["candidates"] = cands;
        ojson nodes = ojson::array();
        for (const TreeNode& n : g.nodes) {
            ojson j = boxJson(n.box, {{"id", n.id}});
            if (n.leaf) {
                ojson ids = ojson::array();
                for (std::uint32_t p : n.prims) ids.push_back(p);
                j["prims"] = ids;
            } else {
                j["axis"] = kAxis[n.axis];
                j["position"] = n.split;
                j["children"] = {n.left, n.right};
            }
            nodes.push_back(j);
        }
        given["tree"] = nodes;
        given["origin"] = jsonVec({g.ray.origin.x, g.ray.origin.y});
        given["dir"] = jsonVec({g.ray.dir.x, g.ray.dir.y});
    }
    d.given = given;
    d.answers = [easy](const Reference& ref) {
        ojson a = {{"pL", ref.number("p-left")},
                   {"pR", ref.number("p-right")},
                   {"cost", ref.number("cost")}};
        if (!easy) {
            a["cheapest"] = ref.choice("cheapest");
            a["visits"] = ref.nodes("test-tree");
        }
        return a;
    };
    d.accept = [easy](const Reference& ref) {
        if (easy) return true;
        const std::size_t visits = ref.nodes("test-tree").size();
        return visits >= 3 && visits <= 8;
    };
    return d;
}

}  // namespace raystep::practice

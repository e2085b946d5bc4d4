// Practice on walking a BVH (lesson 10): the boxes raystep's BVH (SAH) builds over a few circles
// and segments, each listed with its corners, and a ray: which boxes does it enter, in order, and
// how many primitives does it test. easy: siblings never overlap; medium: overlapping siblings
// and a leaf entered whose primitives the ray misses; hard: the ray enters both of two
// overlapping siblings, on more primitives.
#include "course/practice/tree2d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <variant>

namespace raystep::practice {

namespace {

using namespace tree2d;

constexpr const char* kAxis[] = {"x", "y"};

bool shareSpace(const BoxN<2>& a, const BoxN<2>& b) {
    return std::min(a.hi[0], b.hi[0]) > std::max(a.lo[0], b.lo[0]) &&
           std::min(a.hi[1], b.hi[1]) > std::max(a.lo[1], b.lo[1]);
}
bool contains(const BoxN<2>& a, const BoxN<2>& b) {
    return a.lo[0] <= b.lo[0] && a.lo[1] <= b.lo[1] && a.hi[0] >= b.hi[0] && a.hi[1] >= b.hi[1];
}
/// Two boxes overlap as lesson 10 says: they share space and neither lies inside the other.
bool overlap(const BoxN<2>& a, const BoxN<2>& b) {
    return shareSpace(a, b) && !contains(a, b) && !contains(b, a);
}

struct BvhData {
    Scene2D scene;
    std::vector<TreeNode> nodes;
    Ray2 ray;
};

std::optional<BvhData> drawBvh(Random& r, PracticeLevel level) {
    const bool easy = level == PracticeLevel::Easy, hard = level == PracticeLevel::Hard;
    BvhData g;
    const int count = easy ? r.between(3, 4) : hard ? r.between(5, 6) : r.between(4, 5);
    // Overlap needs crowding: the harder levels draw into a smaller area.
    g.scene = drawPrims(r, count, easy ? r.between(7, 9) : r.between(5, 6),
                        easy ? r.between(5, 7) : r.between(4, 5));
    AccelOptions options;
    options.bvh.split = SplitMethod::Sah;
    g.nodes = treeNodes(g.scene, AccelKind::Bvh, options);
    if (g.nodes.size() < 3 || g.nodes.size() > (hard ? 11u : 9u)) return std::nullopt;
    bool anyOverlap = false, anyShared = false;
    for (const TreeNode& n : g.nodes) {
        if (n.leaf) continue;
        const BoxN<2>&a = g.nodes[n.left].box, &b = g.nodes[n.right].box;
        anyOverlap = anyOverlap || overlap(a, b);
        anyShared = anyShared || shareSpace(a, b);
    }
    // easy: siblings share no space at all; above: two siblings overlap.
    if (easy ? anyShared : !anyOverlap) return std::nullopt;
    const auto ray = clearRay(r, g.scene, g.nodes[0].box, g.nodes);
    if (!ray) return std::nullopt;
    g.ray = *ray;
    return g;
}

std::string boxWords(const Scene2D& s, const std::vector<TreeNode>& nodes, bool it) {
    std::string out;
    for (const TreeNode& n : nodes) {
        out += (n.id ? "; " : "") + std::string(it ? "scatola " : "box ") + std::to_string(n.id) +
               " " + corners(n.box, it);
        if (!n.leaf) {
            out += (it ? ", divisa lungo " : ", split along ") + std::string(kAxis[n.axis]) +
                   (it ? ": figli " : ": children ") + std::to_string(n.left) +
                   (it ? " e " : " and ") + std::to_string(n.right);
            continue;
        }
        std::string names;
        for (std::size_t k = 0; k < n.prims.size(); ++k)
            names += (k == 0                    ? ""
                      : k + 1 == n.prims.size() ? (it ? " e " : " and ")
                                                : ", ") +
                     primName(s, n.prims[k], it);
        out += (it ? ": foglia con " : ": a leaf with ") + names;
    }
    return out;
}

/// The walk is one for its level, as the trace shows it: 3 to 8 boxes entered; from medium on a
/// leaf entered whose primitives all miss; at hard both boxes of an overlapping pair entered.
bool walkFits(const Reference& ref, const std::vector<TreeNode>& nodes, PracticeLevel level) {
    const std::vector<int> enters = ref.nodes("enters");
    if (enters.size() < 3 || enters.size() > 8) return false;
    if (level == PracticeLevel::Easy) return true;
    bool missedLeaf = false;
    std::optional<std::uint32_t> leaf;
    bool hitHere = false;
    const auto close = [&] {
        if (leaf && !hitHere) missedLeaf = true;
        leaf.reset();
        hitHere = false;
    };
    for (const Event& e : ref.log().events()) {
        if (const auto* n = std::get_if<NodeEnter>(&e)) {
            close();
            if (nodes[n->node].leaf) leaf = n->node;
        } else if (std::holds_alternative<NodeSkip>(e)) {
            close();
        } else if (const auto* t = std::get_if<PrimitiveTest>(&e)) {
            hitHere = hitHere || t->hit;
        }
    }
    close();
    if (!missedLeaf) return false;
    if (level != PracticeLevel::Hard) return true;
    const auto entered = [&](std::uint32_t id) {
        return std::find(enters.begin(), enters.end(), static_cast<int>(id)) != enters.end();
    };
    for (const TreeNode& n : nodes)
        if (!n.leaf && overlap(nodes[n.left].box, nodes[n.right].box) && entered(n.left) &&
            entered(n.right))
            return true;
    return false;
}

}  // namespace

Draft makeBvh(Random& r, PracticeLevel level) {
    std::optional<BvhData> drawn;
    // A draw fails a rule now and then; thousands in a row would be a bug, not bad luck.
    for (int draws = 0; !(drawn = drawBvh(r, level)); ++draws)
        if (draws > 100000) throw std::logic_error("practice: no draw fits the level");
    const BvhData& g = *drawn;
    const auto rayText = [&](bool it) {
        return (it ? "Il raggio parte da `o = " : "The ray starts at `o = ") +
               vec({g.ray.origin.x, g.ray.origin.y}) +
               (it ? "` con direzione `d = " : "` with direction `d = ") +
               vec({g.ray.dir.x, g.ray.dir.y}) + "`.";
    };
    const std::string en =
        "The primitives: " + primList(g.scene, false) +
        ". The BVH raystep builds over them with the SAH: " + boxWords(g.scene, g.nodes, false) +
        ". " + rayText(false);
    const std::string it = "Le primitive: " + primList(g.scene, true) +
                           ". La BVH che raystep costruisce su di esse con la SAH: " +
                           boxWords(g.scene, g.nodes, true) + ". " + rayText(true);

    Draft d;
    ojson& l = d.lesson;
    l["title"] =
        text("Practice: a ray through a BVH", "Esercitazione: un raggio attraverso una BVH");
    l["text"] = text(
        en +
            " The traversal, as raystep runs it (lesson 10): a box is entered when the slab test "
            "finds the ray in it before the nearest hit found so far; at a node, the first child "
            "listed (the primitives with the lower centres along the node's axis) comes first "
            "when d along that axis is positive, the second when it is negative, and the other "
            "waits on a stack; in a leaf every primitive is tested. Work each answer by hand, then "
            "check it.",
        it +
            " La visita, come la esegue raystep (lezione 10): si entra in una scatola quando il "
            "test degli slab trova il raggio al suo interno prima dell'intersezione più vicina "
            "trovata fino a quel momento; in un nodo viene visitato prima il primo figlio elencato "
            "(le primitive con i centri più bassi lungo l'asse del nodo) se la componente di d "
            "lungo quell'asse è positiva, il secondo se è negativa, e l'altro aspetta su una "
            "pila; in una foglia si testa ogni primitiva. Ricava ogni risposta a mano, poi "
            "verificala.");
    l["scene"] = sceneJson(g.scene, "practice: a few circles and segments for a BVH");
    l["setup"] = {{"accel", "bvh"}, {"split", "sah"}};
    l["views"] = {"2d"};
    l["trace"] = {{"ray", jsonVec({g.ray.origin.x, g.ray.origin.y, g.ray.dir.x, g.ray.dir.y})}};

    ojson ex = ojson::array();
    ojson enters = exercise(
        "enters", "sequence",
        text("Which boxes does the ray enter, in order (box ids separated by spaces)?",
             "In quali scatole entra il raggio, in ordine (gli id delle scatole separati da "
             "spazi)?"));
    enters["of"] = "node_enter";
    enters["hint"] = hints(
        {text(
             "For each box, the slab test: on x, t = (x - o.x) / d.x; on y, t = (y - o.y) / d.y. "
             "The ray is inside from the largest entry to the smallest exit, and misses the box "
             "when that interval is empty.",
             "Per ogni scatola, il test degli slab: su x, t = (x - o.x) / d.x; su y, t = (y - "
             "o.y) / d.y. Il raggio è dentro dal maggiore degli ingressi al minore delle uscite, e "
             "manca la scatola quando l'intervallo è vuoto."),
         text("Boxes may overlap: a ray in the shared space enters both. A box entered does not "
              "mean a primitive hit.",
              "Le scatole possono intersecarsi: un raggio nello spazio condiviso entra in "
              "entrambe. Entrare in una scatola non vuol dire colpire una primitiva.")});
    ex.push_back(enters);
    ojson tests = exercise("tests", "count",
                           text("How many ray-primitive tests does the ray make in this BVH?",
                                "Quanti test raggio-primitiva fa il raggio in questa BVH?"));
    tests["count"] = "primitive_test";
    tests["hint"] = hints({text("A primitive is tested only in a leaf whose box the ray enters.",
                                "Una primitiva viene testata solo in una foglia nella cui scatola "
                                "il raggio entra.")});
    ex.push_back(tests);
    l["exercises"] = ex;

    ojson boxes = ojson::array();
    for (const TreeNode& n : g.nodes) {
        ojson j = boxJson(n.box, {{"id", n.id}});
        if (n.leaf) {
            j["prims"] = n.prims;
        } else {
            j["axis"] = kAxis[n.axis];
            j["children"] = {n.left, n.right};
        }
        boxes.push_back(j);
    }
    ojson given = {{"origin", jsonVec({g.ray.origin.x, g.ray.origin.y})},
                   {"dir", jsonVec({g.ray.dir.x, g.ray.dir.y})},
                   {"boxes", boxes}};
    addPrims(given, g.scene);
    d.given = given;
    d.answers = [](const Reference& ref) {
        return ojson{{"enters", ref.nodes("enters")},
                     {"tests", static_cast<int>(ref.number("tests"))}};
    };
    const std::vector<TreeNode> nodes = g.nodes;
    d.accept = [nodes, level](const Reference& ref) { return walkFits(ref, nodes, level); };
    return d;
}

}  // namespace raystep::practice

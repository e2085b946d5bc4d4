// A full solution of examples/assignments/kdtree/kdtree.cpp (not shipped: tests only), and the
// traversal mistakes it can make on purpose:
//
//   g++ -std=c++17 -O2 kdtree_solution.cpp -o kdtree
//   ./kdtree [tree.jsonl [rays.json]] [--mistake first-hit-in-tree|far-child-first]
//
// Everything above "end of the given code" is the kit's, byte for byte (the test checks it).

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using Vec2 = std::array<double, 2>;
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- Given: the log (one JSON object a line, on stdout) ----

/// A number as JSON: the shortest digits that read back as the same double, "-0.0" with its sign.
std::string number(double v) {
    if (!std::isfinite(v)) return "null";  // JSON has no Infinity
    char buf[40];
    for (int digits = 15; digits <= 17; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    std::string s = buf;
    if (s.find_first_of(".eE") == std::string::npos) s += ".0";  // "-0" would read back as 0
    return s;
}

int nodesLogged = 0;

void logRay(const Vec2& origin, const Vec2& dir) {
    std::printf("{\"ray\": {\"origin\": [%s, %s], \"dir\": [%s, %s]}}\n", number(origin[0]).c_str(),
                number(origin[1]).c_str(), number(dir[0]).c_str(), number(dir[1]).c_str());
}
/// TestTree enters node `id` (every node, interior or leaf, in the order it enters them).
void logNode(int id) {
    ++nodesLogged;
    std::printf("{\"node\": %d}\n", id);
}
/// Primitive `prim` tested (in the leaf logged last).
void logTest(int prim) {
    std::printf("{\"test\": %d}\n", prim);
}
void logHit(int prim, double t) {
    std::printf("{\"hit\": {\"prim\": %d, \"t\": %s}}\n", prim, number(t).c_str());
}
void logMiss() {
    std::printf("{\"miss\": true}\n");
}

// ---- Given: a small JSON reader (no library needed) ----

/// One JSON value: null, true/false, a number, a string, an array or an object.
struct Json {
    enum class Kind { Null, Bool, Number, String, Array, Object };
    Kind kind = Kind::Null;
    bool boolean = false;
    double number = 0.0;
    std::string text;
    std::vector<Json> items;                           // an array's
    std::vector<std::pair<std::string, Json>> fields;  // an object's, in order
    const Json* get(const std::string& key) const {
        for (const auto& f : fields)
            if (f.first == key) return &f.second;
        return nullptr;
    }
};

/// Reads one JSON text; throws std::runtime_error naming the character where it went wrong.
class JsonReader {
  public:
    explicit JsonReader(const std::string& s) : s_(s) {}
    Json document() {
        Json v = value();
        skipSpace();
        if (i_ != s_.size()) fail("text after the value");
        return v;
    }

  private:
    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error(what + " at character " + std::to_string(i_ + 1));
    }
    void skipSpace() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    }
    bool eat(char c) {
        skipSpace();
        if (i_ < s_.size() && s_[i_] == c) {
            ++i_;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!eat(c)) fail(std::string("expected '") + c + "'");
    }
    bool word(const char* w) {
        const std::size_t n = std::strlen(w);
        if (s_.compare(i_, n, w) != 0) return false;
        i_ += n;
        return true;
    }
    Json value() {
        skipSpace();
        if (i_ >= s_.size()) fail("unexpected end of the text");
        Json v;
        const char c = s_[i_];
        if (c == '{') {
            ++i_;
            v.kind = Json::Kind::Object;
            if (eat('}')) return v;
            do {
                skipSpace();
                std::string key = string();
                expect(':');
                v.fields.emplace_back(std::move(key), value());
            } while (eat(','));
            expect('}');
        } else if (c == '[') {
            ++i_;
            v.kind = Json::Kind::Array;
            if (eat(']')) return v;
            do v.items.push_back(value());
            while (eat(','));
            expect(']');
        } else if (c == '"') {
            v.kind = Json::Kind::String;
            v.text = string();
        } else if (word("true")) {
            v.kind = Json::Kind::Bool;
            v.boolean = true;
        } else if (word("false")) {
            v.kind = Json::Kind::Bool;
        } else if (word("null")) {
            v.kind = Json::Kind::Null;
        } else {
            v.kind = Json::Kind::Number;
            v.number = number();
        }
        return v;
    }
    std::string string() {
        if (i_ >= s_.size() || s_[i_] != '"') fail("expected a string");
        std::string out;
        for (++i_; i_ < s_.size() && s_[i_] != '"'; ++i_) {
            if (s_[i_] == '\\') {
                if (++i_ >= s_.size()) break;
                const char e = s_[i_];
                if (e == 'u') fail("\\u escapes are not read here");
                out += e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e;
            } else {
                out += s_[i_];
            }
        }
        if (i_ >= s_.size()) fail("a string without its closing quote");
        ++i_;
        return out;
    }
    double number() {
        // JSON's number characters only: strtod alone would also take "inf", "nan" and hex.
        const std::size_t start = i_;
        if (i_ < s_.size() && s_[i_] == '-') ++i_;
        if (i_ >= s_.size() || !std::isdigit(static_cast<unsigned char>(s_[i_])))
            fail("expected a value");
        while (i_ < s_.size() && std::strchr("0123456789.eE+-", s_[i_]) != nullptr) ++i_;
        const std::string digits = s_.substr(start, i_ - start);
        char* end = nullptr;
        const double x = std::strtod(digits.c_str(), &end);  // "-0.0" and "-0" keep their sign
        if (end != digits.c_str() + digits.size()) fail("a malformed number");
        return x;
    }

    const std::string& s_;
    std::size_t i_ = 0;
};

/// The numbers of a JSON array of n numbers, or an exception naming `what`.
inline std::vector<double> numbersOf(const Json* v, std::size_t n, const std::string& what) {
    if (!v || v->kind != Json::Kind::Array || v->items.size() != n)
        throw std::runtime_error(what + ": expected " + std::to_string(n) + " numbers");
    std::vector<double> out;
    for (const Json& x : v->items) {
        if (x.kind != Json::Kind::Number) throw std::runtime_error(what + ": not a number");
        out.push_back(x.number);
    }
    return out;
}

/// A file's whole text, or an exception naming it.
inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open it");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}
// ---- Given: the tree and the scene, read from tree.jsonl ----
// Written by `raystep-cli assess lecture-kdtree --accel kdtree --structure`, one record a line:
//   {"node": 0, "lo": [x, y], "hi": [x, y], "axis": 0, "split": 3.5, "children": [1, 6]}
//   {"node": 3, "lo": [x, y], "hi": [x, y], "prims": [2, 7]}
//   {"prim": 0, "circle": {"center": [x, y], "radius": r}}
//   {"prim": 11, "segment": {"from": [x, y], "to": [x, y]}}

struct Node {
    bool leaf = false;
    Vec2 lo{}, hi{};  // the node's cell of space
    int axis = 0;     // interior: the split plane is axis = split (0: x, 1: y)
    double split = 0.0;
    int children[2] = {-1, -1};  // interior: [0] below the split, [1] above it
    std::vector<int> prims;      // leaf: the primitives listed in it
};

struct Prim {
    bool circle = false;
    Vec2 center{};  // a circle's
    double radius = 0.0;
    Vec2 from{}, to{};  // a segment's
};

/// The tree: nodes[0] is the root, whose box is the whole tree's.
struct Tree {
    std::vector<Node> nodes;
    std::vector<Prim> prims;
};

namespace detail {
Vec2 vec2(const Json* v, const std::string& what) {
    const std::vector<double> x = numbersOf(v, 2, what);
    return {x[0], x[1]};
}
int wholeNumber(const Json* v, const std::string& what) {
    if (!v || v->kind != Json::Kind::Number || v->number != std::floor(v->number) ||
        v->number < 0 || v->number > 1e9)
        throw std::runtime_error(what + ": expected a whole number");
    return static_cast<int>(v->number);
}
void onlyKeys(const Json& record, std::initializer_list<const char*> keys, const std::string& at) {
    for (const auto& f : record.fields)
        if (std::none_of(keys.begin(), keys.end(), [&](const char* k) { return f.first == k; }))
            throw std::runtime_error(at + ": unexpected key \"" + f.first + "\"");
}
template <typename T>
T& slot(std::vector<T>& v, int id, std::vector<char>& seen, const std::string& at) {
    if (id >= static_cast<int>(v.size())) {
        v.resize(id + 1);
        seen.resize(id + 1, 0);
    }
    if (seen[id]) throw std::runtime_error(at + ": given twice");
    seen[id] = 1;
    return v[id];
}
}  // namespace detail

Tree readTree(const std::string& path) {
    using namespace detail;
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open it (run the --structure command)");
    Tree tree;
    std::vector<char> nodeSeen, primSeen;
    std::string line;
    for (int lineNo = 1; std::getline(in, line); ++lineNo) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank
        const std::string at = path + ":" + std::to_string(lineNo);
        Json r;
        try {
            r = JsonReader(line).document();
        } catch (const std::exception& e) {
            throw std::runtime_error(at + ": " + e.what());
        }
        if (r.kind != Json::Kind::Object) throw std::runtime_error(at + ": not a JSON object");
        if (const Json* id = r.get("node")) {
            const int n = wholeNumber(id, at + ": node");
            Node& node = slot(tree.nodes, n, nodeSeen, at + ": node " + std::to_string(n));
            node.lo = vec2(r.get("lo"), at + ": lo");
            node.hi = vec2(r.get("hi"), at + ": hi");
            if (const Json* prims = r.get("prims")) {
                onlyKeys(r, {"node", "lo", "hi", "prims"}, at);
                if (prims->kind != Json::Kind::Array)
                    throw std::runtime_error(at + ": prims: expected an array");
                node.leaf = true;
                for (const Json& p : prims->items)
                    node.prims.push_back(wholeNumber(&p, at + ": prims"));
            } else {
                onlyKeys(r, {"node", "lo", "hi", "axis", "split", "children"}, at);
                node.axis = wholeNumber(r.get("axis"), at + ": axis");
                if (node.axis > 1) throw std::runtime_error(at + ": axis: 0 or 1 in 2D");
                const Json* split = r.get("split");
                if (!split || split->kind != Json::Kind::Number)
                    throw std::runtime_error(at + ": split: expected a number");
                node.split = split->number;
                const Json* children = r.get("children");
                if (!children || children->kind != Json::Kind::Array || children->items.size() != 2)
                    throw std::runtime_error(at + ": children: expected [below, above]");
                node.children[0] = wholeNumber(&children->items[0], at + ": children");
                node.children[1] = wholeNumber(&children->items[1], at + ": children");
            }
        } else if (const Json* id = r.get("prim")) {
            const int p = wholeNumber(id, at + ": prim");
            Prim& prim = slot(tree.prims, p, primSeen, at + ": prim " + std::to_string(p));
            if (const Json* c = r.get("circle")) {
                onlyKeys(r, {"prim", "circle"}, at);
                onlyKeys(*c, {"center", "radius"}, at + ": circle");
                prim.circle = true;
                prim.center = vec2(c->get("center"), at + ": center");
                const Json* radius = c->get("radius");
                if (!radius || radius->kind != Json::Kind::Number)
                    throw std::runtime_error(at + ": radius: expected a number");
                prim.radius = radius->number;
            } else if (const Json* s = r.get("segment")) {
                onlyKeys(r, {"prim", "segment"}, at);
                onlyKeys(*s, {"from", "to"}, at + ": segment");
                prim.from = vec2(s->get("from"), at + ": from");
                prim.to = vec2(s->get("to"), at + ": to");
            } else {
                throw std::runtime_error(at + ": expected a circle or a segment (a 2D scene)");
            }
        } else {
            throw std::runtime_error(at + ": expected a \"node\" or a \"prim\" record");
        }
    }
    // Every id from 0 up, and every reference to one that exists.
    for (std::size_t n = 0; n < nodeSeen.size(); ++n)
        if (!nodeSeen[n])
            throw std::runtime_error(path + ": node " + std::to_string(n) + " missing");
    for (std::size_t p = 0; p < primSeen.size(); ++p)
        if (!primSeen[p])
            throw std::runtime_error(path + ": prim " + std::to_string(p) + " missing");
    if (tree.nodes.empty()) throw std::runtime_error(path + ": no nodes");
    for (const Node& node : tree.nodes) {
        for (int c : node.children)
            if (!node.leaf && c >= static_cast<int>(tree.nodes.size()))
                throw std::runtime_error(path + ": a child " + std::to_string(c) + " missing");
        for (int p : node.prims)
            if (p >= static_cast<int>(tree.prims.size()))
                throw std::runtime_error(path + ": a leaf's prim " + std::to_string(p) +
                                         " missing");
    }
    return tree;
}

// ---- Given: the ray and its intersections (raystep's own arithmetic) ----

struct Ray {
    Vec2 origin, dir;  // the points origin + t dir, t > 0
};

double cross(const Vec2& a, const Vec2& b) {
    return a[0] * b[1] - a[1] * b[0];
}
double dot(const Vec2& a, const Vec2& b) {
    return a[0] * b[0] + a[1] * b[1];
}

/// The nearest t > 0 where the ray meets the segment, or kInf.
double intersectSegment(const Ray& ray, const Prim& s) {
    const Vec2 e = {s.to[0] - s.from[0], s.to[1] - s.from[1]};
    const double den = cross(ray.dir, e);
    if (den == 0.0) return kInf;  // parallel
    const Vec2 ao = {s.from[0] - ray.origin[0], s.from[1] - ray.origin[1]};
    const double t = cross(ao, e) / den;
    const double u = cross(ao, ray.dir) / den;
    if (!(u >= 0.0 && u <= 1.0) || !(t > 0.0)) return kInf;
    return t;
}

/// The nearest t > 0 where the ray meets the circle, or kInf.
double intersectCircle(const Ray& ray, const Prim& c) {
    // |o + t d - c|^2 = r^2: a t^2 + 2 b t + cc = 0, its discriminant written without cancellation.
    const Vec2 f = {ray.origin[0] - c.center[0], ray.origin[1] - c.center[1]};
    const double a = dot(ray.dir, ray.dir);
    const double b = dot(f, ray.dir);
    const double cc = dot(f, f) - c.radius * c.radius;
    const Vec2 l = {f[0] - (b / a) * ray.dir[0], f[1] - (b / a) * ray.dir[1]};
    const double disc = a * (c.radius * c.radius - dot(l, l));
    if (disc < 0.0) return kInf;
    const double q = -b - std::copysign(std::sqrt(disc), b);
    double t0 = q != 0.0 ? cc / q : 0.0, t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > 0.0) return t0;
    if (t1 > 0.0) return t1;
    return kInf;
}

/// Where the ray is inside the box [lo, hi]: [tNear, tFar] with tNear >= 0; false if it misses.
/// (The root's interval: TestTree starts from it.)
bool intersectBox(const Ray& ray, const Vec2& lo, const Vec2& hi, double& tNear, double& tFar) {
    constexpr double u = std::numeric_limits<double>::epsilon() / 2;
    constexpr double slack = 1 + 2 * (3 * u / (1 - 3 * u));  // rounding: never lose a grazing ray
    tNear = 0.0;
    tFar = kInf;
    for (int i = 0; i < 2; ++i) {
        const double inv = 1.0 / ray.dir[i];
        if (std::isinf(inv)) {  // parallel to this slab: inside it or never
            if (ray.origin[i] < lo[i] || ray.origin[i] > hi[i]) return false;
            continue;
        }
        double t0 = (lo[i] - ray.origin[i]) * inv, t1 = (hi[i] - ray.origin[i]) * inv;
        if (t0 > t1) std::swap(t0, t1);
        t1 *= slack;
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
        if (tNear > tFar) return false;
    }
    return true;
}

/// The nearest hit found so far: prim -1 while there is none.
struct Hit {
    int prim = -1;
    double t = kInf;
};

/// Which primitives this ray has tested already (the mailbox): one per ray.
struct Mailbox {
    explicit Mailbox(std::size_t prims) : tested(prims, 0) {}
    std::vector<char> tested;
};

/// Test primitive `p` for the ray, once per ray (a primitive listed in several leaves is tested in
/// the first of them only), log the test, and keep the nearer hit in `closest` (at the same t,
/// the lower id). The hit's t may lie beyond the current leaf: deciding what that means is yours.
void testPrimitive(const Tree& tree, const Ray& ray, int p, Mailbox& mailbox, Hit& closest) {
    if (mailbox.tested[p]) return;
    mailbox.tested[p] = 1;
    logTest(p);
    const Prim& prim = tree.prims[p];
    const double t = prim.circle ? intersectCircle(ray, prim) : intersectSegment(ray, prim);
    if (t < closest.t || (t == closest.t && t < kInf && p < closest.prim)) closest = {p, t};
}

// ---- Given: the rays to run (rays.json) ----

std::vector<Ray> readRays(const std::string& path) {
    const std::string text = readFile(path);
    const Json doc = JsonReader(text).document();
    const Json* list = doc.get("rays");
    if (!list || list->kind != Json::Kind::Array)
        throw std::runtime_error(path + ": expected {\"rays\": [...]}");
    std::vector<Ray> rays;
    for (const Json& r : list->items) {
        const std::vector<double> o = numbersOf(r.get("origin"), 2, path + ": a ray's origin");
        const std::vector<double> d = numbersOf(r.get("dir"), 2, path + ": a ray's dir");
        rays.push_back({{o[0], o[1]}, {d[0], d[1]}});
    }
    return rays;
}

// ---- end of the given code ----

// ---- The solution ----

// far-child-first is not one of docs/assignment-format.md's names: raystep reports it unnamed.
const char* const kMistakes[] = {"first-hit-in-tree", "far-child-first"};
std::string mistake;  // empty: the right traversal

/// TestTree, front to back with a stack: log every node entered, near child first, and stop
/// when the nearest hit so far lies before the next node's tNear.
Hit testTree(const Tree& tree, const Ray& ray) {
    Hit closest;
    Mailbox mailbox(tree.prims.size());
    double tNear, tFar;
    if (!intersectBox(ray, tree.nodes[0].lo, tree.nodes[0].hi, tNear, tFar)) return closest;
    struct ToVisit {
        int node;
        double tNear, tFar;
    };
    std::vector<ToVisit> toVisit;
    int id = 0;
    for (;;) {
        // The early exit: the hit lies before this node, and before every node on the stack.
        if (closest.prim >= 0 && closest.t < tNear) break;
        logNode(id);
        const Node& node = tree.nodes[id];
        if (!node.leaf) {
            const int a = node.axis;
            const double o = ray.origin[a], d = ray.dir[a];
            // raystep's tSplit, rounding bounded by 4 eps: the children's intervals overlap by
            // that much rather than leave a gap (only a ray through a corner can tell).
            const double tSplit = (node.split - o) * (1.0 / d);
            constexpr double eps = std::numeric_limits<double>::epsilon();
            const double tSplitLo = tSplit * (1 - 4 * eps), tSplitHi = tSplit * (1 + 4 * eps);
            const bool belowFirst =
                mistake == "far-child-first" || o < node.split || (o == node.split && d <= 0);
            const int nearChild = node.children[belowFirst ? 0 : 1];
            const int farChild = node.children[belowFirst ? 1 : 0];
            if (!(tSplit > 0) || tSplitLo > tFar) {
                id = nearChild;  // the plane is behind the ray or beyond this node
            } else if (tSplitHi < tNear) {
                id = farChild;  // the ray crosses the plane before it enters this node
            } else {
                toVisit.push_back({farChild, std::max(tSplitLo, tNear), tFar});
                id = nearChild;
                tFar = std::min(tSplitHi, tFar);
            }
            continue;
        }
        for (int p : node.prims) testPrimitive(tree, ray, p, mailbox, closest);
        if (mistake == "first-hit-in-tree" && closest.prim >= 0) break;
        if (toVisit.empty()) break;
        id = toVisit.back().node;
        tNear = toVisit.back().tNear;
        tFar = toVisit.back().tFar;
        toVisit.pop_back();
    }
    return closest;
}

int main(int argc, char** argv) {
    std::string treePath = "tree.jsonl", raysPath = "rays.json";
    int positional = 0;
    for (int a = 1; a < argc; ++a) {
        if (std::strcmp(argv[a], "--mistake") == 0 && a + 1 < argc) {
            mistake = argv[++a];
            if (std::find_if(std::begin(kMistakes), std::end(kMistakes),
                             [](const char* m) { return mistake == m; }) == std::end(kMistakes)) {
                std::fprintf(stderr, "kdtree: --mistake %s: not one of this traversal's\n",
                             mistake.c_str());
                return 2;
            }
        } else {
            (positional++ == 0 ? treePath : raysPath) = argv[a];
        }
    }
    Tree tree;
    std::vector<Ray> rays;
    try {
        tree = readTree(treePath);
        rays = readRays(raysPath);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "kdtree: %s\n", e.what());
        return 2;
    }
    for (const Ray& r : rays) {
        logRay(r.origin, r.dir);
        const Hit hit = testTree(tree, r);
        if (hit.prim >= 0)
            logHit(hit.prim, hit.t);
        else
            logMiss();
    }
    return 0;
}

// A full solution of examples/assignments/dda-3d/dda3d.cpp (not shipped: tests only), and the named
// mistakes of docs/assignment-format.md it can make on purpose:
//
//   g++ -std=c++17 -O2 dda3d_solution.cpp -o dda3d && ./dda3d [rays.json] [--mistake NAME]
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
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using Vec3 = std::array<double, 3>;
using Cell = std::array<int, 3>;
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- Given: the log (one JSON object a line, on stdout) ----

/// A number as JSON: the shortest digits that read back as the same double, "-0.0" with its sign,
/// null for an infinity (JSON has none: an infinite tMax, on an axis the ray is parallel to).
std::string number(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[40];
    for (int digits = 15; digits <= 17; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    std::string s = buf;
    if (s.find_first_of(".eE") == std::string::npos) s += ".0";  // "-0" would read back as 0
    return s;
}

std::string numbers(const Vec3& v) {
    return "[" + number(v[0]) + ", " + number(v[1]) + ", " + number(v[2]) + "]";
}

int cellsLogged = 0;

void logRay(const Vec3& origin, const Vec3& dir) {
    std::printf("{\"ray\": {\"origin\": %s, \"dir\": %s}}\n", numbers(origin).c_str(),
                numbers(dir).c_str());
}

/// A cell the walk visits, [X, Y, Z], with its tMaxX, tMaxY, tMaxZ.
void logCell(const Cell& cell, const Vec3& tMax) {
    ++cellsLogged;
    std::printf("{\"cell\": [%d, %d, %d], \"tMax\": %s}\n", cell[0], cell[1], cell[2],
                numbers(tMax).c_str());
}

/// The same without tMax (raystep then checks the cells only).
void logCell(const Cell& cell) {
    ++cellsLogged;
    std::printf("{\"cell\": [%d, %d, %d]}\n", cell[0], cell[1], cell[2]);
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
// ---- Given: the rays to run (rays.json) ----

struct Grid {
    Cell res;  // cells per axis
    Vec3 lo, hi;
};

struct Ray {
    Vec3 origin, dir;
};

void readRays(const std::string& path, Grid& grid, std::vector<Ray>& rays) {
    const std::string text = readFile(path);
    const Json doc = JsonReader(text).document();
    const Json* g = doc.get("grid");
    const Json* list = doc.get("rays");
    if (!g || !list || list->kind != Json::Kind::Array)
        throw std::runtime_error(path + ": expected {\"grid\": ..., \"rays\": [...]}");
    const std::vector<double> res = numbersOf(g->get("res"), 3, path + ": grid res");
    const std::vector<double> lo = numbersOf(g->get("min"), 3, path + ": grid min");
    const std::vector<double> hi = numbersOf(g->get("max"), 3, path + ": grid max");
    for (int i = 0; i < 3; ++i) {
        grid.res[i] = static_cast<int>(res[i]);
        grid.lo[i] = lo[i];
        grid.hi[i] = hi[i];
    }
    for (const Json& r : list->items) {
        const std::vector<double> o = numbersOf(r.get("origin"), 3, path + ": a ray's origin");
        const std::vector<double> d = numbersOf(r.get("dir"), 3, path + ": a ray's dir");
        rays.push_back({{o[0], o[1], o[2]}, {d[0], d[1], d[2]}});
    }
}

// ---- end of the given code ----

// ---- The solution ----

// The named mistakes of docs/assignment-format.md this walk can make on purpose.
const char* const kMistakes[] = {"start-cell-skipped",     "negative-direction-boundary",
                                 "parallel-axis-division", "negative-zero",
                                 "tie-one-axis",           "no-entry-clip",
                                 "no-exit-check"};
std::string mistake;  // empty: the right walk
// no-exit-check: the walk goes on past the grid for this many cells, so that it ends.
constexpr int kCellsBeyond = 64;

void walk(const Grid& grid, const Vec3& o, const Vec3& d) {
    Vec3 VSize;
    for (int i = 0; i < 3; ++i) VSize[i] = (grid.hi[i] - grid.lo[i]) / grid.res[i];

    // Where the ray enters the grid (slab by slab); a zero component is parallel to that axis.
    double tEnter = 0.0, tExit = kInf;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) {
            if (o[i] < grid.lo[i] || o[i] > grid.hi[i]) return;
            continue;
        }
        double t0 = (grid.lo[i] - o[i]) / d[i], t1 = (grid.hi[i] - o[i]) / d[i];
        if (t0 > t1) std::swap(t0, t1);
        tEnter = std::max(tEnter, t0);
        tExit = std::min(tExit, t1);
    }
    if (!(tEnter < tExit)) return;  // misses the grid, or only touches it

    Cell X, step;
    Vec3 tMax;
    for (int i = 0; i < 3; ++i) {
        if (mistake == "parallel-axis-division")
            step[i] = d[i] > 0 ? 1 : -1;
        else if (mistake == "negative-zero")
            step[i] = d[i] >= 0 ? 1 : -1;
        else
            step[i] = d[i] > 0 ? 1 : (d[i] < 0 ? -1 : 0);
        const double p = mistake == "no-entry-clip" ? o[i] : o[i] + tEnter * d[i];
        const double f = (p - grid.lo[i]) / VSize[i];
        // The cell the ray goes into: on a boundary moving down, the one below it.
        const double c =
            step[i] < 0 && mistake != "no-entry-clip" ? std::ceil(f) - 1 : std::floor(f);
        X[i] = static_cast<int>(std::clamp(c, 0.0, double(grid.res[i] - 1)));
    }
    Vec3 tDelta;
    for (int i = 0; i < 3; ++i) {
        // The first boundary ahead: X + 1 moving up, X moving down.
        const int k = step[i] > 0 || mistake == "negative-direction-boundary" ? X[i] + 1 : X[i];
        tMax[i] = step[i] != 0 ? (grid.lo[i] + k * VSize[i] - o[i]) / d[i] : kInf;
        tDelta[i] = step[i] != 0 ? VSize[i] / std::abs(d[i]) : kInf;
    }

    int beyond = 0;
    for (bool first = true;; first = false) {
        if (!(first && mistake == "start-cell-skipped")) logCell(X, tMax);
        // The axis of the smallest tMax, by the slides' comparisons (the later axis at a tie).
        int a = 0;
        for (int i = 1; i < 3; ++i)
            if (!(tMax[a] < tMax[i])) a = i;
        const double t = tMax[a];
        if (t == kInf) break;  // no boundary ahead on any axis (a zero direction)
        bool out = false;
        for (int i = 0; i < 3; ++i) {
            // At an exact tie every tied axis steps (tie-one-axis: the slides' one, a).
            if (i != a && (mistake == "tie-one-axis" || tMax[i] != t)) continue;
            X[i] += step[i];
            tMax[i] += tDelta[i];  // the slides' tMaxX += tDeltaX
            out = out || X[i] < 0 || X[i] >= grid.res[i];
        }
        if (out && (mistake != "no-exit-check" || ++beyond > kCellsBeyond)) break;
    }
}

int main(int argc, char** argv) {
    std::string path = "rays.json";
    for (int a = 1; a < argc; ++a) {
        if (std::strcmp(argv[a], "--mistake") == 0 && a + 1 < argc) {
            mistake = argv[++a];
            if (std::find_if(std::begin(kMistakes), std::end(kMistakes),
                             [](const char* m) { return mistake == m; }) == std::end(kMistakes)) {
                std::fprintf(stderr, "dda3d: --mistake %s: not one of this walk's\n",
                             mistake.c_str());
                return 2;
            }
        } else {
            path = argv[a];
        }
    }
    Grid grid;
    std::vector<Ray> rays;
    try {
        readRays(path, grid, rays);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "dda3d: %s\n", e.what());
        return 2;
    }
    for (const Ray& r : rays) {
        logRay(r.origin, r.dir);
        walk(grid, r.origin, r.dir);
    }
    return 0;
}

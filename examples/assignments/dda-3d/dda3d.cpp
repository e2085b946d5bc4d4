// The lecture's 3D DDA (Amanatides & Woo 1987): the cells a ray visits on a regular grid, logged
// as JSON Lines for raystep to check. Write walk() at the bottom (the TODOs); the rest is given.
//
//   g++ -std=c++17 -O2 dda3d.cpp -o dda3d
//   ./dda3d > walk.jsonl
//   raystep-cli assess dda --grid 6,4,4 --min -3,-2,0 --max 3,2,2 --trace walk.jsonl
//
// The rays come from rays.json (or the file named on the command line). TASK.md says what the
// walk must do and how to read raystep's verdict.

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

// ---- Your walk ----

/// Log, in order, every cell the ray o + t d (t >= 0) visits on `grid`: from the cell where the
/// ray enters the grid to the one where it leaves it. A ray that misses the grid logs no cell.
void walk(const Grid& grid, const Vec3& o, const Vec3& d) {
    // The size of a cell along each axis: the slides' VSizeX, VSizeY, VSizeZ.
    const double VSizeX = (grid.hi[0] - grid.lo[0]) / grid.res[0];
    const double VSizeY = (grid.hi[1] - grid.lo[1]) / grid.res[1];
    const double VSizeZ = (grid.hi[2] - grid.lo[2]) / grid.res[2];

    // TODO 1. Where the ray enters the grid: tEnter = 0 if the origin is inside, else the t where
    // it crosses into the grid's box (the slab test, axis by axis); and tExit, where it leaves.
    // A ray that misses the box, or only touches it (tEnter >= tExit), visits no cell: return.
    // A zero component of d (0.0 or -0.0) is parallel to that axis: no slab crossing there.

    // TODO 2. The set-up, per axis (X shown; Y and Z alike):
    //   stepX   = +1, -1, or 0 when dx is zero (the ray never crosses an X boundary);
    //   X       = the cell of the entry point o + tEnter d (if that point lies exactly on a
    //             boundary, the cell the ray goes into: the lower one when stepX = -1);
    //   tMaxX   = the t of the first X boundary ahead: boundary X + 1 when stepX = +1, boundary X
    //             when stepX = -1, infinite when stepX = 0;
    //   tDeltaX = VSizeX / |dx|, the t between two X boundaries.

    // TODO 3. The loop: log the cell, logCell({X, Y, Z}, {tMaxX, tMaxY, tMaxZ}), then step
    // across the smallest tMax (tMaxX += tDeltaX, X += stepX, as in the slides). At an exact tie
    // step every tied axis at once: the ray goes through an edge or a vertex of the grid and only
    // touches the cells beside it. Stop when a step leaves the grid.

    (void)VSizeX, (void)VSizeY, (void)VSizeZ, (void)o, (void)d;  // delete once you use them
}

int main(int argc, char** argv) {
    const std::string path = argc > 1 ? argv[1] : "rays.json";
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
    if (cellsLogged == 0) {
        // Not a finished walk: every kit's ray list has rays that visit cells.
        std::fprintf(stderr, "dda3d: walk() logged no cell: write its TODOs (TASK.md)\n");
        return 1;
    }
    return 0;
}

// compute: a hand computation from the data the prompt gives (a ray and a shape, or a kd node
// and a plane); the answer comes from raystep's kernels (course/compute.h), not the trace.
#include "course/exercises/kind_unit.h"

#include "course/compute.h"

#include "raystep/base/i18n.h"

#include <algorithm>
#include <cmath>

namespace raystep::exercises {

namespace {

using detail::json;
using Reader = LessonReader;

/// A vector of 2 or 3 numbers (`lengths` says which), appended to `numbers` as written.
std::array<double, 3> readVector(const Reader& r, const json& j, const std::string& path,
                                 int lengths, std::vector<double>& numbers, int* length = nullptr) {
    const bool two = lengths & 2, three = lengths & 1;
    if (!j.is_array() || !((two && j.size() == 2) || (three && j.size() == 3)))
        r.fail(path, std::string("expected an array of ") +
                         (two && three ? "2 or 3"
                          : two        ? "2"
                                       : "3") +
                         " numbers, got " + Reader::typeName(j));
    std::array<double, 3> v{0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < j.size(); ++i) {
        v[i] = r.number(j[i], JsonLineMap::element(path, i));
        numbers.push_back(v[i]);
    }
    if (length) *length = static_cast<int>(j.size());
    return v;
}
constexpr int kThree = 1, kTwoOrThree = 3;

ComputeGiven readGiven(const Reader& r, const json& j, const std::string& path) {
    using Shape = ComputeGiven::Shape;
    r.requireObject(j, path);
    r.checkKeys(
        j, path,
        {"ray", "sphere", "triangle", "plane", "box", "grid", "node", "nl", "nr", "shading"});
    ComputeGiven g;
    auto& nums = g.numbers;
    const auto child = [&](const char* key) { return JsonLineMap::child(path, key); };
    if (j.contains("shading")) {
        g.shape = Shape::Shading;
        if (j.size() != 1) r.fail(path, "Phong shading's data are all under \"shading\"");
        const std::string sp = child("shading");
        const json& s = j["shading"];
        r.requireObject(s, sp);
        r.checkKeys(s, sp, {"n", "l", "v", "kd", "ks", "shininess", "intensity"});
        for (const char* key : {"n", "l", "kd", "intensity"})
            if (!s.contains(key))
                r.fail(sp, std::string("Phong shading needs \"") + key +
                               "\" (and \"v\", \"ks\", \"shininess\" for the specular term)");
        const auto unit = [&](const char* key) {
            const std::string kp = JsonLineMap::child(sp, key);
            const std::array<double, 3> v = readVector(r, s[key], kp, kThree, nums);
            // phong() takes unit vectors: a longer one would scale the terms unnoticed.
            if (std::abs(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] - 1.0) > 1e-9)
                r.fail(kp, "expected a unit vector (length 1)");
            return v;
        };
        const auto value = [&](const char* key) {
            const std::string kp = JsonLineMap::child(sp, key);
            const double v = r.number(s[key], kp);
            if (!(v >= 0.0)) r.fail(kp, "expected a number >= 0");
            nums.push_back(v);
            return v;
        };
        g.normal = unit("n");
        g.toLight = unit("l");
        g.kd = value("kd");
        g.intensity = value("intensity");
        const int specularKeys = s.contains("v") + s.contains("ks") + s.contains("shininess");
        if (specularKeys != 0 && specularKeys != 3)
            r.fail(sp, "the specular term needs all of \"v\", \"ks\" and \"shininess\"");
        g.specular = specularKeys == 3;
        if (g.specular) {
            g.toViewer = unit("v");
            if (!(g.normal[0] * g.toViewer[0] + g.normal[1] * g.toViewer[1] +
                      g.normal[2] * g.toViewer[2] >
                  0.0))
                r.fail(JsonLineMap::child(sp, "v"),
                       "the eye must be on the normal's side of the surface (n.v > 0)");
            g.ks = value("ks");
            g.shininess = value("shininess");
        }
        return g;
    }
    if (j.contains("node")) {
        g.shape = Shape::Node;
        for (const char* key : {"plane", "nl", "nr"})
            if (!j.contains(key))
                r.fail(path, std::string("a node's SAH cost needs \"") + key + "\"");
        for (const char* key : {"ray", "sphere", "triangle", "box", "grid"})
            if (j.contains(key)) r.fail(child(key), "a node's SAH cost takes no ray or shape");
        const std::string np = child("node");
        r.requireObject(j["node"], np);
        r.checkKeys(j["node"], np, {"min", "max"});
        if (!j["node"].contains("min") || !j["node"].contains("max"))
            r.fail(np, "expected {\"min\": [..], \"max\": [..]}");
        int n1 = 0, n2 = 0;
        g.lo =
            readVector(r, j["node"]["min"], JsonLineMap::child(np, "min"), kTwoOrThree, nums, &n1);
        g.hi =
            readVector(r, j["node"]["max"], JsonLineMap::child(np, "max"), kTwoOrThree, nums, &n2);
        if (n1 != n2) r.fail(JsonLineMap::child(np, "max"), "min and max differ in length");
        g.dims = n1;
        for (int i = 0; i < g.dims; ++i)
            if (!(g.hi[i] > g.lo[i])) r.fail(np, "max must be above min on every axis");
        const std::string pp = child("plane");
        r.requireObject(j["plane"], pp);
        r.checkKeys(j["plane"], pp, {"axis", "at"});
        if (!j["plane"].contains("axis") || !j["plane"].contains("at"))
            r.fail(pp, "expected {\"axis\": \"x\", \"at\": P}");
        const std::string ap = JsonLineMap::child(pp, "axis");
        const std::string axis = r.string(j["plane"]["axis"], ap);
        g.axis = axis == "x" ? 0 : axis == "y" ? 1 : axis == "z" ? 2 : -1;
        if (g.axis < 0 || g.axis >= g.dims)
            r.fail(ap, g.dims == 2 ? "expected \"x\" or \"y\"" : "expected \"x\", \"y\" or \"z\"");
        const std::string atp = JsonLineMap::child(pp, "at");
        g.at = r.number(j["plane"]["at"], atp);
        nums.push_back(g.at);
        if (!(g.at > g.lo[g.axis] && g.at < g.hi[g.axis]))
            r.fail(atp, "the plane must lie strictly inside the node");
        g.nl = r.integer(j["nl"], child("nl"), 0, 1'000'000);
        g.nr = r.integer(j["nr"], child("nr"), 0, 1'000'000);
        nums.push_back(g.nl);
        nums.push_back(g.nr);
        return g;
    }
    for (const char* key : {"nl", "nr"})
        if (j.contains(key)) r.fail(child(key), "only a node's SAH cost takes this key");
    if (!j.contains("ray"))
        r.fail(path, "the given data needs its \"ray\": {\"o\": .., \"d\": ..}");
    int shapes = 0;
    for (const char* key : {"sphere", "triangle", "plane", "box", "grid"})
        shapes += j.contains(key);
    if (shapes != 1)
        r.fail(path,
               "give the ray and exactly one of \"sphere\", \"triangle\", \"plane\", \"box\", "
               "\"grid\" (or a \"node\" with its \"plane\", \"nl\", \"nr\", or "
               "\"shading\")");
    const bool grid = j.contains("grid");
    const std::string rp = child("ray");
    r.requireObject(j["ray"], rp);
    r.checkKeys(j["ray"], rp, {"o", "d"});
    if (!j["ray"].contains("o") || !j["ray"].contains("d"))
        r.fail(rp, "expected {\"o\": [..], \"d\": [..]}");
    int no = 0, nd = 0;
    g.o = readVector(r, j["ray"]["o"], JsonLineMap::child(rp, "o"), grid ? kTwoOrThree : kThree,
                     nums, &no);
    g.d = readVector(r, j["ray"]["d"], JsonLineMap::child(rp, "d"), grid ? kTwoOrThree : kThree,
                     nums, &nd);
    if (no != nd) r.fail(JsonLineMap::child(rp, "d"), "o and d differ in length");
    g.dims = no;
    if (g.d[0] == 0.0 && g.d[1] == 0.0 && g.d[2] == 0.0)
        r.fail(JsonLineMap::child(rp, "d"), "the direction must not be zero");
    if (j.contains("sphere")) {
        g.shape = Shape::Sphere;
        const std::string sp = child("sphere");
        r.requireObject(j["sphere"], sp);
        r.checkKeys(j["sphere"], sp, {"c", "r"});
        if (!j["sphere"].contains("c") || !j["sphere"].contains("r"))
            r.fail(sp, "expected {\"c\": [x, y, z], \"r\": R}");
        g.center = readVector(r, j["sphere"]["c"], JsonLineMap::child(sp, "c"), kThree, nums);
        g.radius = r.positive(j["sphere"]["r"], JsonLineMap::child(sp, "r"));
        nums.push_back(g.radius);
    } else if (j.contains("triangle")) {
        g.shape = Shape::Triangle;
        const std::string tp = child("triangle");
        if (!j["triangle"].is_array() || j["triangle"].size() != 3)
            r.fail(tp, "expected three corners [[x, y, z], [x, y, z], [x, y, z]]");
        for (std::size_t i = 0; i < 3; ++i)
            g.tri[i] = readVector(r, j["triangle"][i], JsonLineMap::element(tp, i), kThree, nums);
    } else if (j.contains("plane")) {
        g.shape = Shape::Plane;
        const std::string pp = child("plane");
        r.requireObject(j["plane"], pp);
        r.checkKeys(j["plane"], pp, {"n", "k"});
        if (!j["plane"].contains("n") || !j["plane"].contains("k"))
            r.fail(pp, "expected {\"n\": [x, y, z], \"k\": K} (the points p with p.n = k)");
        g.normal = readVector(r, j["plane"]["n"], JsonLineMap::child(pp, "n"), kThree, nums);
        g.k = r.number(j["plane"]["k"], JsonLineMap::child(pp, "k"));
        nums.push_back(g.k);
    } else if (j.contains("box")) {
        g.shape = Shape::Box;
        const std::string bp = child("box");
        r.requireObject(j["box"], bp);
        r.checkKeys(j["box"], bp, {"min", "max"});
        if (!j["box"].contains("min") || !j["box"].contains("max"))
            r.fail(bp, "expected {\"min\": [x, y, z], \"max\": [x, y, z]}");
        g.lo = readVector(r, j["box"]["min"], JsonLineMap::child(bp, "min"), kThree, nums);
        g.hi = readVector(r, j["box"]["max"], JsonLineMap::child(bp, "max"), kThree, nums);
        for (int i = 0; i < 3; ++i)
            if (!(g.hi[i] > g.lo[i])) r.fail(bp, "max must be above min on every axis");
    } else {
        g.shape = Shape::Grid;
        const std::string gp = child("grid");
        r.requireObject(j["grid"], gp);
        r.checkKeys(j["grid"], gp, {"min", "cell", "res"});
        if (!j["grid"].contains("min") || !j["grid"].contains("cell"))
            r.fail(gp,
                   "expected {\"min\": [..], \"cell\": [..]} (and \"res\": [..] cells per axis)");
        const int lengths = g.dims == 2 ? 2 : kThree;
        g.lo = readVector(r, j["grid"]["min"], JsonLineMap::child(gp, "min"), lengths, nums);
        g.hi = readVector(r, j["grid"]["cell"], JsonLineMap::child(gp, "cell"), lengths, nums);
        for (int i = 0; i < g.dims; ++i)
            if (!(g.hi[i] > 0.0))
                r.fail(JsonLineMap::child(gp, "cell"), "a cell's size must be greater than 0");
        ifPresent(j["grid"], gp, "res", [&](const json& v, const std::string& p) {
            if (!v.is_array() || static_cast<int>(v.size()) != g.dims)
                r.fail(p, "expected " + std::to_string(g.dims) + " whole numbers (cells per axis)");
            for (int i = 0; i < g.dims; ++i) {
                g.res[i] = r.integer(v[i], JsonLineMap::element(p, i), 1, 1'000'000);
                nums.push_back(g.res[i]);
            }
        });
    }
    return g;
}

/// The quantities a Compute exercise may ask of its shape.
std::vector<std::string> computeQuantities(const ComputeGiven& g) {
    using Shape = ComputeGiven::Shape;
    switch (g.shape) {
        case Shape::Sphere:
            return {"a", "b", "c", "discriminant", "t0", "t1", "t"};
        case Shape::Triangle:
            return {"t", "u", "v", "n.dir"};
        case Shape::Plane:
            return {"n.dir", "t"};
        case Shape::Box:
            return {"t_enter", "t_exit"};
        case Shape::Grid: {
            std::vector<std::string> q;
            for (const char* what : {"tMax.", "tDelta.", "cell."})
                for (int i = 0; i < g.dims; ++i) q.push_back(what + std::string(1, "xyz"[i]));
            return q;
        }
        case Shape::Node:
            return {"pL", "pR", "sahCost"};
        case Shape::Shading:
            if (g.specular) return {"n.l", "diffuse", "r.v", "specular"};
            return {"n.l", "diffuse"};
    }
    return {};
}

class Compute final : public OneNumberUnit {
  public:
    ExerciseKind kind() const override { return ExerciseKind::Compute; }
    std::string_view name() const override { return "compute"; }
    std::vector<const char*> keys() const override { return {"given", "quantity"}; }

    void read(const LessonReader& r, const detail::json& j, const std::string& path,
              Exercise& ex) const override {
        for (const char* key : {"given", "quantity"})
            if (!j.contains(key))
                r.fail(path, std::string("a compute exercise needs \"") + key + "\"");
        ex.given = readGiven(r, j["given"], JsonLineMap::child(path, "given"));
        const std::string qp = JsonLineMap::child(path, "quantity");
        ex.computeQuantity = r.string(j["quantity"], qp);
        const auto allowed = computeQuantities(ex.given);
        if (std::find(allowed.begin(), allowed.end(), ex.computeQuantity) == allowed.end()) {
            std::string names;
            for (const auto& n : allowed) names += (names.empty() ? "" : ", ") + n;
            r.fail(qp, "this shape's quantities are " + names);
        }
    }

    Reference reference(const Context& c, Language lang) const override {
        Reference ref;
        Answer& a = ref.answer;
        std::string& why = ref.why;
        a.numbers.push_back(computeAnswer(c.ex, c.file));
        why = computeWorking(c.ex, lang);
        return ref;
    }

    std::string slip(const Context& c, const Answer& given, const Reference&, const std::string&,
                     Language lang) const override {
        return computeSlip(c.ex, given.numbers[0], lang);
    }

    std::string retryAdvice(const Exercise&, bool, Language lang) const override {
        return tr(lang,
                  "Work it again by hand from the data the prompt gives: the trace does "
                  "not hold them.");
    }
    bool answerInTrace() const override { return false; }
    AnswerInputSpec input(const Exercise&) const override {
        return {AnswerInputSpec::Widget::Number};
    }
    std::string placeholder(const Exercise&, int, Language lang) const override {
        return tr(lang, "your result, a number (e.g. -2.5 or 0,75)");
    }
    const std::vector<double>* givenNumbers(const Exercise& ex) const override {
        return &ex.given.numbers;
    }

    void answerForms(const LeakInput& in, AnswerForms& f) const override {
        const Answer a = referenceAnswer(in.ex, in.log, in.file, in.sweep);
        addLeakNumber(f, a.numbers.at(0));
        f.describe = formatNumber(a.numbers[0]);
    }
};

}  // namespace

const ExerciseKindUnit& computeUnit() {
    static const Compute unit;
    return unit;
}

}  // namespace raystep::exercises

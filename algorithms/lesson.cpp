#include "raystep/lesson.h"

#include "raystep/base/json_reader.h"
#include "raystep/geometry/kernels.h"
#include "raystep/base/names.h"
#include "raystep/trace/replay.h"
#include "raystep/scene/resources.h"
#include "raystep/scene/scene_loader.h"
#include "raystep/render/tracer.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

namespace raystep {

using detail::ifPresent;
using detail::json;
using Reader = detail::JsonReader<LessonError>;

namespace {

constexpr NameTable<ExerciseKind, 5> kExerciseKinds{{{ExerciseKind::NextCell, "next_cell"},
                                                     {ExerciseKind::Value, "value"},
                                                     {ExerciseKind::PickSplit, "pick_split"},
                                                     {ExerciseKind::Count, "count"},
                                                     {ExerciseKind::HitOrMiss, "hit_or_miss"}}};
constexpr NameTable<Quantity, 17> kQuantities{{{Quantity::TMaxX, "tMax.x"},
                                               {Quantity::TMaxY, "tMax.y"},
                                               {Quantity::TMaxZ, "tMax.z"},
                                               {Quantity::TDeltaX, "tDelta.x"},
                                               {Quantity::TDeltaY, "tDelta.y"},
                                               {Quantity::TDeltaZ, "tDelta.z"},
                                               {Quantity::TEnter, "t_enter"},
                                               {Quantity::TExit, "t_exit"},
                                               {Quantity::HitT, "hit.t"},
                                               {Quantity::HitU, "hit.u"},
                                               {Quantity::HitV, "hit.v"},
                                               {Quantity::TestT, "test.t"},
                                               {Quantity::NodeTNear, "node.tNear"},
                                               {Quantity::NodeTFar, "node.tFar"},
                                               {Quantity::CandidatePL, "candidate.pL"},
                                               {Quantity::CandidatePR, "candidate.pR"},
                                               {Quantity::CandidateCost, "candidate.sahCost"}}};
constexpr NameTable<LessonView, 3> kViews{
    {{LessonView::View2D, "2d"}, {LessonView::View3D, "3d"}, {LessonView::Image, "image"}}};

std::optional<std::size_t> eventKindNamed(std::string_view name) {
    for (std::size_t i = 0; i < kEventNames.size(); ++i)
        if (kEventNames[i] == name) return i;
    return std::nullopt;
}
std::string eventKindList() {
    std::string s;
    for (const auto n : kEventNames) s += (s.empty() ? "" : ", ") + std::string(n);
    return s;
}

std::string fmt(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

// ---- reading lesson files ----

LocalText readText(const Reader& r, const json& j, const std::string& path) {
    // A string, or an array of lines (easier to write and review than one long string).
    const auto one = [&](const json& v, const std::string& p) {
        if (v.is_string()) return v.get<std::string>();
        if (!v.is_array())
            r.fail(p, "expected a string or an array of lines, got " + Reader::typeName(v));
        std::string s;
        for (std::size_t i = 0; i < v.size(); ++i) {
            if (i) s += '\n';
            s += r.string(v[i], JsonLineMap::element(p, i));
        }
        return s;
    };
    r.requireObject(j, path);
    r.checkKeys(j, path, {"en", "it"});
    if (!j.contains("en")) r.fail(path, "the English text \"en\" is required");
    LocalText t;
    t.en = one(j["en"], JsonLineMap::child(path, "en"));
    ifPresent(j, path, "it", [&](const json& v, const std::string& p) { t.it = one(v, p); });
    if (t.en.empty()) r.fail(JsonLineMap::child(path, "en"), "must not be empty");
    return t;
}

ReplayPosition readPosition(const Reader& r, const json& j, const std::string& path) {
    ReplayPosition at;
    if (j.is_string()) {
        const auto s = j.get<std::string>();
        if (s == "start") return at;
        if (s == "end") {
            at.mode = ReplayPosition::Mode::End;
            return at;
        }
        r.fail(path,
               "expected \"start\", \"end\", a number of events, or {\"after\" | "
               "\"before\": EVENT, \"nth\": N}");
    }
    if (j.is_number()) {
        at.mode = ReplayPosition::Mode::Cursor;
        at.cursor = static_cast<std::size_t>(r.integer(j, path, 0, 100'000'000));
        return at;
    }
    r.requireObject(j, path);
    r.checkKeys(j, path, {"after", "before", "nth"});
    const bool after = j.contains("after"), before = j.contains("before");
    if (after == before) r.fail(path, "give exactly one of \"after\" and \"before\"");
    const std::string key = after ? "after" : "before";
    const std::string kindPath = JsonLineMap::child(path, key);
    const auto kind = eventKindNamed(r.string(j[key], kindPath));
    if (!kind) r.fail(kindPath, "unknown event kind (expected one of " + eventKindList() + ")");
    at.mode = after ? ReplayPosition::Mode::AfterEvent : ReplayPosition::Mode::BeforeEvent;
    at.eventKind = *kind;
    ifPresent(j, path, "nth", [&](const json& v, const std::string& p) {
        at.nth = r.integer(v, p, 1, 100'000'000);
    });
    return at;
}

void readSetup(const Reader& r, const json& j, const std::string& path, Lesson& l) {
    r.requireObject(j, path);
    r.checkKeys(j, path,
                {"accel", "split", "mailbox", "grid_res", "grid_lambda", "leaf_size", "max_depth",
                 "c_trav", "c_isect", "empty_bonus", "buckets"});
    AccelOptions& o = l.options;
    ifPresent(j, path, "accel", [&](const json& v, const std::string& p) {
        const auto k = parseAccelKind(r.string(v, p));
        if (!k) r.fail(p, "expected bruteforce, grid, kdtree or bvh");
        l.accel = *k;
    });
    ifPresent(j, path, "split", [&](const json& v, const std::string& p) {
        const auto s = parseSplitMethod(r.string(v, p));
        if (!s) r.fail(p, "expected midpoint, median or sah");
        o.kdtree.split = o.bvh.split = *s;
    });
    ifPresent(j, path, "mailbox", [&](const json& v, const std::string& p) {
        if (!v.is_boolean()) r.fail(p, "expected true or false, got " + Reader::typeName(v));
        o.grid.mailbox = o.kdtree.mailbox = v.get<bool>();
    });
    ifPresent(j, path, "grid_res", [&](const json& v, const std::string& p) {
        if (!v.is_array() || v.size() < 2 || v.size() > 3)
            r.fail(p, "expected [NX, NY] or [NX, NY, NZ], got " + Reader::typeName(v));
        std::array<int, 3> res{1, 1, 1};
        for (std::size_t i = 0; i < v.size(); ++i)
            res[i] = r.integer(v[i], JsonLineMap::element(p, i), 1, GridOptions::kMaxCellsPerAxis);
        const std::size_t cells = std::size_t(res[0]) * res[1] * res[2];
        if (cells > GridOptions::kMaxCells)
            r.fail(p, std::to_string(cells) + " cells, more than the grid's " +
                          std::to_string(GridOptions::kMaxCells) + " (2^24)");
        o.grid.res = res;
    });
    ifPresent(j, path, "grid_lambda",
              [&](const json& v, const std::string& p) { o.grid.lambda = r.positive(v, p); });
    ifPresent(j, path, "leaf_size", [&](const json& v, const std::string& p) {
        o.kdtree.leafSize = o.bvh.leafSize = r.integer(v, p, 1, 1'000'000);
    });
    ifPresent(j, path, "max_depth", [&](const json& v, const std::string& p) {
        o.kdtree.maxDepth = r.integer(v, p, 1, 60);
    });
    ifPresent(j, path, "c_trav", [&](const json& v, const std::string& p) {
        o.kdtree.cTrav = o.bvh.cTrav = r.nonNegative(v, p);
    });
    ifPresent(j, path, "c_isect", [&](const json& v, const std::string& p) {
        o.kdtree.cIsect = o.bvh.cIsect = r.positive(v, p);
    });
    ifPresent(j, path, "empty_bonus", [&](const json& v, const std::string& p) {
        o.kdtree.emptyBonus = r.nonNegative(v, p);
        if (o.kdtree.emptyBonus > 1.0) r.fail(p, "must be between 0 and 1");
    });
    ifPresent(j, path, "buckets", [&](const json& v, const std::string& p) {
        o.bvh.buckets = r.integer(v, p, 2, 256);
    });
}

std::array<int, 2> readPair(const Reader& r, const json& j, const std::string& path, int lo,
                            int hi) {
    if (!j.is_array() || j.size() != 2)
        r.fail(path, "expected an array of 2 whole numbers, got " + Reader::typeName(j));
    return {r.integer(j[0], JsonLineMap::element(path, 0), lo, hi),
            r.integer(j[1], JsonLineMap::element(path, 1), lo, hi)};
}

void readTrace(const Reader& r, const json& j, const std::string& path, LessonTrace& t) {
    r.requireObject(j, path);
    r.checkKeys(j, path, {"ray", "pixel", "image", "build"});
    const int forms = int(j.contains("ray")) + int(j.contains("pixel")) + int(j.contains("build"));
    if (forms != 1) r.fail(path, "give exactly one of \"ray\", \"pixel\" and \"build\"");
    if (j.contains("build")) {
        const std::string p = JsonLineMap::child(path, "build");
        if (j["build"] != true) r.fail(p, "expected true");
        t.kind = LessonTrace::Kind::Build;
    } else if (j.contains("ray")) {
        const std::string p = JsonLineMap::child(path, "ray");
        const json& v = j["ray"];
        if (v == "example") {
            t.kind = LessonTrace::Kind::ExampleRay;
        } else {
            if (!v.is_array() || v.size() != 4)
                r.fail(p, "expected \"example\" or [OX, OY, DX, DY]");
            double n[4];
            for (int i = 0; i < 4; ++i) n[i] = r.number(v[i], JsonLineMap::element(p, i));
            if (n[2] == 0.0 && n[3] == 0.0) r.fail(p, "the direction must not be zero");
            if (const auto problem =
                    rayRangeProblem(Precision::Double, std::max(std::abs(n[0]), std::abs(n[1])),
                                    std::max(std::abs(n[2]), std::abs(n[3]))))
                r.fail(p, *problem);
            t.kind = LessonTrace::Kind::Ray2D;
            t.ray = Ray2{Vec2(n[0], n[1]), Vec2(n[2], n[3])};
        }
    } else {
        t.kind = LessonTrace::Kind::Pixel;
        const auto xy = readPair(r, j["pixel"], JsonLineMap::child(path, "pixel"), 0, 8192);
        t.x = xy[0];
        t.y = xy[1];
    }
    ifPresent(j, path, "image", [&](const json& v, const std::string& p) {
        const auto wh = readPair(r, v, p, 1, 8192);
        t.width = wh[0];
        t.height = wh[1];
    });
    if (t.kind == LessonTrace::Kind::Pixel && (t.x >= t.width || t.y >= t.height))
        r.fail(JsonLineMap::child(path, "pixel"), "outside the " + std::to_string(t.width) + "x" +
                                                      std::to_string(t.height) + " image");
}

Exercise readExercise(const Reader& r, const json& j, const std::string& path) {
    r.requireObject(j, path);
    r.checkKeys(j, path,
                {"id", "type", "at", "prompt", "hint", "quantity", "count", "ray_kind", "ray_depth",
                 "until", "with_t", "tolerance"});
    Exercise ex;
    ex.line = r.lines().lineOf(path);
    for (const char* key : {"id", "type", "prompt"})
        if (!j.contains(key)) r.fail(path, std::string("\"") + key + "\" is required");
    ex.id = r.string(j["id"], JsonLineMap::child(path, "id"));
    if (ex.id.empty() || ex.id.find_first_of(" \t\n\"") != std::string::npos)
        r.fail(JsonLineMap::child(path, "id"), "an exercise id is one word, e.g. \"next-cell\"");
    const std::string typePath = JsonLineMap::child(path, "type");
    const auto kind = valueNamed(kExerciseKinds, r.string(j["type"], typePath));
    if (!kind) r.fail(typePath, "expected next_cell, value, pick_split, count or hit_or_miss");
    ex.kind = *kind;
    ex.prompt = readText(r, j["prompt"], JsonLineMap::child(path, "prompt"));
    ifPresent(j, path, "hint",
              [&](const json& v, const std::string& p) { ex.hint = readText(r, v, p); });
    ifPresent(j, path, "at",
              [&](const json& v, const std::string& p) { ex.at = readPosition(r, v, p); });
    ifPresent(j, path, "tolerance", [&](const json& v, const std::string& p) {
        ex.tolerance = r.positive(v, p);
        if (ex.tolerance >= 1.0) r.fail(p, "a tolerance of 100% or more accepts anything");
    });
    const auto onlyFor = [&](const char* key, ExerciseKind k) {
        if (j.contains(key) && ex.kind != k)
            r.fail(JsonLineMap::child(path, key),
                   "only " + std::string(exerciseKindName(k)) + " exercises take this key");
    };
    onlyFor("quantity", ExerciseKind::Value);
    onlyFor("count", ExerciseKind::Count);
    onlyFor("ray_kind", ExerciseKind::Count);
    onlyFor("ray_depth", ExerciseKind::Count);
    onlyFor("until", ExerciseKind::Count);
    ifPresent(j, path, "until",
              [&](const json& v, const std::string& p) { ex.until = readPosition(r, v, p); });
    onlyFor("with_t", ExerciseKind::HitOrMiss);
    if (ex.kind == ExerciseKind::Value) {
        if (!j.contains("quantity")) r.fail(path, "a value exercise names its \"quantity\"");
        const std::string p = JsonLineMap::child(path, "quantity");
        const auto q = valueNamed(kQuantities, r.string(j["quantity"], p));
        if (!q) {
            std::string names;
            for (const auto& [v, n] : kQuantities)
                names += (names.empty() ? "" : ", ") + std::string(n);
            r.fail(p, "unknown quantity (expected one of " + names + ")");
        }
        ex.quantity = *q;
    }
    if (ex.kind == ExerciseKind::Count) {
        if (!j.contains("count")) r.fail(path, "a count exercise names the event it counts");
        const std::string p = JsonLineMap::child(path, "count");
        const auto k = eventKindNamed(r.string(j["count"], p));
        if (!k) r.fail(p, "unknown event kind (expected one of " + eventKindList() + ")");
        ex.countKind = *k;
        ifPresent(j, path, "ray_kind", [&](const json& v, const std::string& rp) {
            const std::string name = r.string(v, rp);
            for (int i = 0; i < kRayKindCount; ++i)
                if (kRayKindNames[i] == name) ex.rayKind = static_cast<RayKind>(i);
            if (!ex.rayKind)
                r.fail(rp, "expected primary, shadow, reflection, refraction or diffuse");
            if (ex.countKind != variantIndex<RayBegin>())
                r.fail(rp, "only a count of ray_begin events can name a ray kind");
        });
        ifPresent(j, path, "ray_depth", [&](const json& v, const std::string& rp) {
            ex.rayDepth = r.integer(v, rp, 0, 64);
            if (ex.countKind != variantIndex<RayBegin>())
                r.fail(rp, "only a count of ray_begin events can name a ray depth");
        });
    }
    ifPresent(j, path, "with_t", [&](const json& v, const std::string& p) {
        if (!v.is_boolean()) r.fail(p, "expected true or false");
        ex.withT = v.get<bool>();
    });
    return ex;
}

LessonStep readStep(const Reader& r, const json& j, const std::string& path) {
    r.requireObject(j, path);
    r.checkKeys(j, path, {"text", "at", "filter", "camera"});
    LessonStep s;
    s.line = r.lines().lineOf(path);
    if (!j.contains("text")) r.fail(path, "a step needs its \"text\"");
    s.text = readText(r, j["text"], JsonLineMap::child(path, "text"));
    ifPresent(j, path, "at",
              [&](const json& v, const std::string& p) { s.at = readPosition(r, v, p); });
    ifPresent(j, path, "filter",
              [&](const json& v, const std::string& p) { s.filter = r.string(v, p); });
    ifPresent(j, path, "camera", [&](const json& v, const std::string& p) {
        r.requireObject(v, p);
        r.checkKeys(v, p, {"azimuth", "elevation", "zoom"});
        LessonCamera c;
        ifPresent(v, p, "azimuth",
                  [&](const json& x, const std::string& xp) { c.azimuth = r.number(x, xp); });
        ifPresent(v, p, "elevation", [&](const json& x, const std::string& xp) {
            c.elevation = r.number(x, xp);
            if (std::abs(c.elevation) >= 90.0) r.fail(xp, "must be between -90 and 90 degrees");
        });
        ifPresent(v, p, "zoom",
                  [&](const json& x, const std::string& xp) { c.zoom = r.positive(x, xp); });
        s.camera = c;
    });
    return s;
}

constexpr std::string_view kLessonPrefix = "lessons/";

}  // namespace

std::optional<Language> parseLanguage(std::string_view code) {
    if (code == "en") return Language::En;
    if (code == "it") return Language::It;
    return std::nullopt;
}

std::string_view exerciseKindName(ExerciseKind k) {
    return nameOf(kExerciseKinds, k);
}
std::optional<Quantity> parseQuantity(std::string_view name) {
    return valueNamed(kQuantities, name);
}
std::string_view quantityName(Quantity q) {
    return nameOf(kQuantities, q);
}

const Exercise* Lesson::exercise(std::string_view exerciseId) const {
    for (const Exercise& e : exercises)
        if (e.id == exerciseId) return &e;
    return nullptr;
}

namespace {
Lesson readLesson(std::string_view text, const std::string& fileName) {
    auto parsed = detail::parseJsonFile<LessonError>(text, fileName);
    const json& root = parsed.root;
    const Reader r(fileName, std::move(parsed.lines));
    r.requireObject(root, "");
    r.checkKeys(root, "",
                {"format", "version", "id", "number", "title", "text", "scene", "setup", "views",
                 "trace", "sweep", "steps", "exercises"});
    if (root.value("format", json()) != "raystep-lesson")
        r.fail("format", "a lesson file starts with \"format\": \"raystep-lesson\"");
    if (!root.contains("version")) r.fail("", "\"version\" is required (1)");
    if (r.integer(root["version"], "version", 1, 1000) != 1)
        r.fail("version", "this raystep reads lesson files of version 1");
    for (const char* key : {"id", "number", "title", "text", "scene", "trace"})
        if (!root.contains(key)) r.fail("", std::string("\"") + key + "\" is required");
    Lesson l;
    l.file = fileName;
    l.id = r.string(root["id"], "id");
    if (l.id.empty() || l.id.find_first_of(" \t\n/\"") != std::string::npos)
        r.fail("id", "a lesson id is one word without '/', e.g. \"grid-2d-dda\"");
    l.number = r.integer(root["number"], "number", 1, 999);
    l.title = readText(r, root["title"], "title");
    l.text = readText(r, root["text"], "text");
    l.scene = r.string(root["scene"], "scene");
    if (l.scene.empty()) r.fail("scene", "must name a built-in scene or a scene file");
    ifPresent(root, "", "setup",
              [&](const json& v, const std::string& p) { readSetup(r, v, p, l); });
    readTrace(r, root["trace"], "trace", l.trace);
    ifPresent(root, "", "views", [&](const json& v, const std::string& p) {
        if (!v.is_array() || v.empty())
            r.fail(p, "expected a list of views: \"2d\", \"3d\", \"image\"");
        for (std::size_t i = 0; i < v.size(); ++i) {
            const std::string ep = JsonLineMap::element(p, i);
            const auto view = valueNamed(kViews, r.string(v[i], ep));
            if (!view) r.fail(ep, "expected \"2d\", \"3d\" or \"image\"");
            l.views.push_back(*view);
        }
    });
    ifPresent(root, "", "sweep", [&](const json& v, const std::string& p) {
        r.requireObject(v, p);
        r.checkKeys(v, p, {"grid_res", "image"});
        GridSweepSpec s;
        const std::string rp = JsonLineMap::child(p, "grid_res");
        if (!v.contains("grid_res") || !v["grid_res"].is_array() || v["grid_res"].empty())
            r.fail(rp, "expected a list of resolutions (cells per axis)");
        for (std::size_t i = 0; i < v["grid_res"].size(); ++i)
            // The sweep's grids are cubes: 256^3 is the grid's cap of 2^24 cells.
            s.resolutions.push_back(
                r.integer(v["grid_res"][i], JsonLineMap::element(rp, i), 1, 256));
        ifPresent(v, p, "image", [&](const json& x, const std::string& xp) {
            const auto wh = readPair(r, x, xp, 1, 1024);
            s.width = wh[0];
            s.height = wh[1];
        });
        l.sweep = s;
    });
    ifPresent(root, "", "steps", [&](const json& v, const std::string& p) {
        if (!v.is_array()) r.fail(p, "expected an array of steps");
        for (std::size_t i = 0; i < v.size(); ++i)
            l.steps.push_back(readStep(r, v[i], JsonLineMap::element(p, i)));
    });
    ifPresent(root, "", "exercises", [&](const json& v, const std::string& p) {
        if (!v.is_array()) r.fail(p, "expected an array of exercises");
        for (std::size_t i = 0; i < v.size(); ++i) {
            const std::string ep = JsonLineMap::element(p, i);
            Exercise ex = readExercise(r, v[i], ep);
            if (l.exercise(ex.id)) r.fail(JsonLineMap::child(ep, "id"), "exercise id used twice");
            l.exercises.push_back(std::move(ex));
        }
    });
    const bool twoDTrace =
        l.trace.kind == LessonTrace::Kind::ExampleRay || l.trace.kind == LessonTrace::Kind::Ray2D;
    if (l.views.empty())
        l.views = twoDTrace ? std::vector<LessonView>{LessonView::View2D}
                            : std::vector<LessonView>{LessonView::View3D, LessonView::Image};
    if (l.trace.kind == LessonTrace::Kind::Build && l.accel != AccelKind::KdTree &&
        l.accel != AccelKind::Bvh)
        r.fail("trace", "a build can be recorded for a kdtree or a bvh (setup.accel)");
    return l;
}

/// A file's text, or a LessonError "PATH: cannot read the WHAT: why".
std::string readLessonFile(const std::string& path, const std::string& what) {
    try {
        return detail::readRegularFile(path, detail::kMaxJsonFileBytes);
    } catch (const detail::ReadFailure& f) {
        throw LessonError(path, 0, "", "cannot read the " + what + ": " + f.what());
    }
}
}  // namespace

Lesson loadLessonText(std::string_view text, const std::string& fileName) {
    return detail::guarded<LessonError>(fileName, [&] { return readLesson(text, fileName); });
}

std::vector<Lesson> builtinLessons() {
    std::vector<Lesson> lessons;
    for (const std::string& f : embeddedFileNames())
        if (f.starts_with(kLessonPrefix) && f.ends_with(".json")) {
            lessons.push_back(loadLessonText(*embeddedFile(f), f));
            lessons.back().builtin = true;
        }
    std::sort(lessons.begin(), lessons.end(),
              [](const Lesson& a, const Lesson& b) { return a.number < b.number; });
    return lessons;
}

Lesson loadLesson(const std::string& idOrPath) {
    for (Lesson& l : builtinLessons())
        if (l.id == idOrPath || std::to_string(l.number) == idOrPath) return std::move(l);
    std::string text;
    try {
        text = detail::readRegularFile(idOrPath, detail::kMaxJsonFileBytes);
    } catch (const detail::ReadFailure& f) {
        if (!f.missing())
            throw LessonError(idOrPath, 0, "",
                              std::string("cannot read the lesson file: ") + f.what());
        std::string ids;
        for (const Lesson& l : builtinLessons())
            ids += (ids.empty() ? "" : ", ") + std::to_string(l.number) + " " + l.id;
        throw LessonError(idOrPath, 0, "",
                          "no such lesson file, and no built-in lesson of that id or number "
                          "(built-in: " +
                              ids + ")");
    }
    return loadLessonText(text, idOrPath);
}

// ---- running a lesson ----

std::string lessonScenePath(const Lesson& lesson) {
    // Where the lesson came from decides, not its path's text (a lecturer's lessons/my.json).
    if (lesson.builtin || embeddedFile(lesson.scene + ".json")) return lesson.scene;
    // A scene file next to the lesson file.
    const std::filesystem::path p(lesson.scene);
    if (p.is_absolute()) return lesson.scene;
    return (std::filesystem::path(lesson.file).parent_path() / p).string();
}

std::unique_ptr<EventLog> recordLessonTrace(const Lesson& lesson,
                                            const std::variant<Scene, Scene2D>& scene,
                                            const Accelerator* accel3D,
                                            const Accelerator2D* accel2D) {
    auto log = std::make_unique<EventLog>();
    const LessonTrace& t = lesson.trace;
    const auto* s2 = std::get_if<Scene2D>(&scene);
    const auto* s3 = std::get_if<Scene>(&scene);
    const auto fail = [&](const std::string& message) {
        throw LessonError(lesson.file, 0, "trace", message);
    };
    switch (t.kind) {
        case LessonTrace::Kind::Build:
            if (s2)
                buildAccelerator2D(*s2, lesson.accel, lesson.options, log.get());
            else
                buildAccelerator(*s3, lesson.accel, {}, lesson.options, *log);
            break;
        case LessonTrace::Kind::ExampleRay:
        case LessonTrace::Kind::Ray2D: {
            if (!s2) fail("a 2D ray needs a 2D scene; " + printable(lesson.scene) + " is 3D");
            if (t.kind == LessonTrace::Kind::ExampleRay && !s2->exampleRay)
                fail("the scene " + printable(lesson.scene) + " has no example ray");
            traceRay2D(*accel2D, t.kind == LessonTrace::Kind::Ray2D ? t.ray : *s2->exampleRay,
                       *log);
            break;
        }
        case LessonTrace::Kind::Pixel:
            if (!s3) fail("a pixel needs a 3D scene; " + printable(lesson.scene) + " is 2D");
            tracePixelEvents(*s3, *accel3D, t.x, t.y, t.width, t.height, *log);
            break;
    }
    return log;
}

LessonRun runLesson(const Lesson& lesson) {
    LessonRun run;
    try {
        run.scene =
            std::make_unique<std::variant<Scene, Scene2D>>(loadAnyScene(lessonScenePath(lesson)));
    } catch (const SceneError& e) {
        throw LessonError(lesson.file, 0, "scene", e.what());
    }
    if (const auto* s2 = std::get_if<Scene2D>(run.scene.get()))
        run.accel2D = buildAccelerator2D(*s2, lesson.accel, lesson.options);
    else
        run.accel3D =
            buildAccelerator(std::get<Scene>(*run.scene), lesson.accel, {}, lesson.options);
    run.log = recordLessonTrace(lesson, *run.scene, run.accel3D ? &*run.accel3D : nullptr,
                                run.accel2D ? &*run.accel2D : nullptr);
    return run;
}

std::optional<std::size_t> resolvePosition(const ReplayPosition& at, const EventLog& log) {
    const auto& ev = log.events();
    switch (at.mode) {
        case ReplayPosition::Mode::Start:
            return 0;
        case ReplayPosition::Mode::End:
            return ev.size();
        case ReplayPosition::Mode::Cursor:
            if (at.cursor > ev.size()) return std::nullopt;
            return at.cursor;
        case ReplayPosition::Mode::AfterEvent:
        case ReplayPosition::Mode::BeforeEvent: {
            int seen = 0;
            for (std::size_t i = 0; i < ev.size(); ++i)
                if (ev[i].index() == at.eventKind && ++seen == at.nth)
                    return at.mode == ReplayPosition::Mode::AfterEvent ? i + 1 : i;
            return std::nullopt;
        }
    }
    return std::nullopt;
}

std::string describePosition(const ReplayPosition& at, Language lang) {
    const bool it = lang == Language::It;
    switch (at.mode) {
        case ReplayPosition::Mode::Start:
            return it ? "l'inizio" : "the start";
        case ReplayPosition::Mode::End:
            return it ? "la fine" : "the end";
        case ReplayPosition::Mode::Cursor:
            return (it ? "l'evento " : "event ") + std::to_string(at.cursor);
        case ReplayPosition::Mode::AfterEvent:
        case ReplayPosition::Mode::BeforeEvent: {
            const bool after = at.mode == ReplayPosition::Mode::AfterEvent;
            return std::string(after ? (it ? "dopo" : "after") : (it ? "prima di" : "before")) +
                   " " + std::string(kEventNames[at.eventKind]) + (it ? " numero " : " number ") +
                   std::to_string(at.nth);
        }
    }
    return "?";
}

// ---- answers ----

namespace {

std::optional<double> parseNumber(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    if (s.empty()) return std::nullopt;
    std::string copy(s);
    std::replace(copy.begin(), copy.end(), ',', '.');  // "0,75" as Italian students write it
    double v = 0.0;
    const auto [end, ec] = std::from_chars(copy.data(), copy.data() + copy.size(), v);
    if (ec != std::errc() || end != copy.data() + copy.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::vector<std::string_view> splitAny(std::string_view s, std::string_view seps) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= s.size(); ++i)
        if (i == s.size() || seps.find(s[i]) != std::string_view::npos) {
            if (i > start) parts.push_back(s.substr(start, i - start));
            start = i + 1;
        }
    return parts;
}

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool close(double answer, double reference, double tolerance) {
    return std::abs(answer - reference) <= tolerance * std::max(1.0, std::abs(reference));
}

/// The first event of type E at or after `from`, with its index.
template <typename E>
std::optional<std::pair<std::size_t, E>> nextEvent(const EventLog& log, std::size_t from) {
    const auto& ev = log.events();
    for (std::size_t i = from; i < ev.size(); ++i)
        if (const E* e = std::get_if<E>(&ev[i])) return std::pair{i, *e};
    return std::nullopt;
}
/// The last event of type E before `before`.
template <typename E>
std::optional<E> previousEvent(const EventLog& log, std::size_t before) {
    const auto& ev = log.events();
    for (std::size_t i = std::min(before, ev.size()); i-- > 0;)
        if (const E* e = std::get_if<E>(&ev[i])) return *e;
    return std::nullopt;
}

int dimsOf(const EventLog& log, std::size_t at) {
    if (auto s = previousEvent<DdaSetup>(log, at + 1)) return s->dims;
    if (auto s = nextEvent<DdaSetup>(log, 0)) return s->second.dims;
    return 3;
}

std::string cellText(const std::array<std::int32_t, 3>& c, int dims) {
    std::string s = "(";
    for (int i = 0; i < dims; ++i) s += (i ? ", " : "") + std::to_string(c[i]);
    return s + ")";
}
std::string axesText(unsigned axes) {
    std::string s;
    for (int i = 0; i < 3; ++i)
        if (axes & (1u << i)) s += "XYZ"[i];
    return s;
}
const char* axisName(int a) {
    return a == 0 ? "x" : a == 1 ? "y" : "z";
}

/// Two-language feedback: picks the language's text.
std::string tr2(Language lang, const std::string& en, const std::string& it) {
    return lang == Language::It ? it : en;
}

struct Context {
    const Exercise& ex;
    const EventLog& log;
    const std::string& file;
    std::size_t at;
    [[noreturn]] void fail(const std::string& message) const {
        throw LessonError(file, ex.line, "exercises." + ex.id, message);
    }
};

Context contextOf(const Exercise& ex, const EventLog& log, const std::string& file) {
    Context c{ex, log, file, 0};
    const auto at = resolvePosition(ex.at, log);
    if (!at) c.fail("its position (" + describePosition(ex.at) + ") is not in the trace");
    c.at = *at;
    return c;
}

/// The reference answer and the trace's explanation of it.
std::pair<Answer, std::string> reference(const Context& c, Language lang) {
    Answer a;
    std::string why;
    const EventLog& log = c.log;
    switch (c.ex.kind) {
        case ExerciseKind::NextCell: {
            const auto next = nextEvent<DdaCell>(log, c.at);
            if (!next) c.fail("no DDA cell follows its position in the trace");
            const int dims = dimsOf(log, next->first);
            for (int i = 0; i < dims; ++i) a.numbers.push_back(next->second.cell[i]);
            const auto before = previousEvent<DdaCell>(log, next->first);
            if (!before) {
                why = tr2(lang,
                          "The walk starts in the cell that contains the ray's entry point "
                          "(t_enter): " +
                              cellText(next->second.cell, dims) + ".",
                          "La visita comincia dalla cella che contiene il punto d'ingresso del "
                          "raggio (t_enter): " +
                              cellText(next->second.cell, dims) + ".");
            } else {
                std::string tmax;
                for (int i = 0; i < dims; ++i)
                    tmax += std::string(i ? ", " : "") + "tMax" + "XYZ"[i] + " = " +
                            fmt(before->tMax[i]);
                const std::string axes = axesText(next->second.axes);
                why = tr2(
                    lang,
                    "In cell " + cellText(before->cell, dims) + " the DDA compares " + tmax +
                        ": the smallest is along " + axes + ", so it steps in " + axes + " to " +
                        cellText(next->second.cell, dims) +
                        (axes.size() > 1 ? " (a tie: the ray passes through a corner)" : "") + ".",
                    "Nella cella " + cellText(before->cell, dims) + " il DDA confronta " + tmax +
                        ": il minore è lungo " + axes + ", quindi avanza in " + axes + " fino a " +
                        cellText(next->second.cell, dims) +
                        (axes.size() > 1 ? " (pareggio: il raggio passa per un vertice)" : "") +
                        ".");
            }
            break;
        }
        case ExerciseKind::Value: {
            const Quantity q = c.ex.quantity;
            double v = 0.0;
            std::string source;
            if (q >= Quantity::TMaxX && q <= Quantity::TMaxZ) {
                const auto e = nextEvent<DdaCell>(log, c.at);
                if (!e) c.fail("no DDA cell follows its position");
                v = e->second.tMax[static_cast<int>(q) - static_cast<int>(Quantity::TMaxX)];
                source = "dda_cell " + cellText(e->second.cell, dimsOf(log, e->first));
            } else if (q >= Quantity::TDeltaX && q <= Quantity::TExit) {
                const auto e = nextEvent<DdaSetup>(log, c.at);
                if (!e) c.fail("no DDA set-up follows its position");
                v = q == Quantity::TEnter ? e->second.tEnter
                    : q == Quantity::TExit
                        ? e->second.tExit
                        : e->second
                              .tDelta[static_cast<int>(q) - static_cast<int>(Quantity::TDeltaX)];
                source = "dda_setup";
            } else if (q >= Quantity::HitT && q <= Quantity::HitV) {
                const auto e = nextEvent<RayHit>(log, c.at);
                if (!e) c.fail("no hit follows its position");
                v = q == Quantity::HitT   ? e->second.t
                    : q == Quantity::HitU ? e->second.u
                                          : e->second.v;
                source = "ray_hit (primitive " + std::to_string(e->second.prim) + ")";
            } else if (q == Quantity::TestT) {
                std::optional<PrimitiveTest> hit;
                for (std::size_t i = c.at; i < log.events().size() && !hit; ++i)
                    if (const auto* t = std::get_if<PrimitiveTest>(&log.events()[i]); t && t->hit)
                        hit = *t;
                if (!hit) c.fail("no primitive test that hits follows its position");
                v = hit->t;
                source = "primitive_test (primitive " + std::to_string(hit->prim) + ")";
            } else if (q == Quantity::NodeTNear || q == Quantity::NodeTFar) {
                const auto e = nextEvent<NodeEnter>(log, c.at);
                if (!e) c.fail("no node is entered after its position");
                v = q == Quantity::NodeTNear ? e->second.tNear : e->second.tFar;
                source = "node_enter (node " + std::to_string(e->second.node) + ")";
            } else {
                const auto e = nextEvent<SplitCandidate>(log, c.at);
                if (!e) c.fail("no split candidate follows its position");
                const SplitCandidate& s = e->second;
                v = q == Quantity::CandidatePL   ? s.pl
                    : q == Quantity::CandidatePR ? s.pr
                                                 : s.sahCost;
                source = std::string("split_candidate ") + axisName(s.axis) + " = " +
                         fmt(s.position) + " (NL " + std::to_string(s.nl) + ", NR " +
                         std::to_string(s.nr) + ", P(L|C) " + fmt(s.pl) + ", P(R|C) " + fmt(s.pr) +
                         ", cost " + fmt(s.sahCost) + ")";
            }
            if (!std::isfinite(v))
                c.fail("the trace's value is not finite (the ray never crosses)");
            a.numbers.push_back(v);
            why = tr2(lang,
                      "The trace records " + std::string(quantityName(q)) + " = " + fmt(v) +
                          " in the event " + source + ".",
                      "La traccia registra " + std::string(quantityName(q)) + " = " + fmt(v) +
                          " nell'evento " + source + ".");
            break;
        }
        case ExerciseKind::PickSplit: {
            const auto node = nextEvent<BuildNode>(log, c.at);
            if (!node) c.fail("no node is built after its position");
            std::optional<SplitCandidate> best;
            int count = 0;
            for (const Event& e : log.events())
                if (const auto* s = std::get_if<SplitCandidate>(&e);
                    s && s->node == node->second.node) {
                    ++count;
                    if (!best || s->sahCost < best->sahCost) best = *s;
                }
            if (!best) c.fail("node " + std::to_string(node->second.node) + " has no candidates");
            a.numbers = {static_cast<double>(best->axis), best->position};
            const std::string formula = "C_trav + C_isect (" + fmt(best->pl) + " x " +
                                        std::to_string(best->nl) + " + " + fmt(best->pr) + " x " +
                                        std::to_string(best->nr) + ")";
            why = tr2(
                lang,
                "Of the " + std::to_string(count) + " candidates of node " +
                    std::to_string(node->second.node) + ", the cheapest is " +
                    axisName(best->axis) + " = " + fmt(best->position) +
                    ": NL = " + std::to_string(best->nl) + ", NR = " + std::to_string(best->nr) +
                    ", cost " + formula + " = " + fmt(best->sahCost) + ".",
                "Tra i " + std::to_string(count) + " candidati del nodo " +
                    std::to_string(node->second.node) + ", il meno costoso è " +
                    axisName(best->axis) + " = " + fmt(best->position) +
                    ": NL = " + std::to_string(best->nl) + ", NR = " + std::to_string(best->nr) +
                    ", costo " + formula + " = " + fmt(best->sahCost) + ".");
            break;
        }
        case ExerciseKind::Count: {
            std::size_t n = 0, end = log.events().size();
            if (c.ex.until) {
                const auto u = resolvePosition(*c.ex.until, log);
                if (!u || *u < c.at)
                    c.fail("its end (" + describePosition(*c.ex.until) +
                           ") is not in the trace after its start");
                end = *u;
            }
            for (std::size_t i = c.at; i < end; ++i) {
                const Event& e = log.events()[i];
                if (e.index() != c.ex.countKind) continue;
                if (const auto* b = std::get_if<RayBegin>(&e)) {
                    if (c.ex.rayKind && b->kind != *c.ex.rayKind) continue;
                    if (c.ex.rayDepth && b->depth != *c.ex.rayDepth) continue;
                }
                ++n;
            }
            a.numbers.push_back(static_cast<double>(n));
            const std::string what =
                std::string(kEventNames[c.ex.countKind]) +
                (c.ex.rayKind ? " " + std::string(kRayKindNames[static_cast<int>(*c.ex.rayKind)])
                              : std::string()) +
                (c.ex.rayDepth ? " depth " + std::to_string(*c.ex.rayDepth) : std::string());
            why = tr2(
                lang,
                "The trace holds " + std::to_string(n) + " events " + what + " from " +
                    describePosition(c.ex.at) + " to " +
                    describePosition(
                        c.ex.until.value_or(ReplayPosition{ReplayPosition::Mode::End})) +
                    ".",
                "La traccia contiene " + std::to_string(n) + " eventi " + what + " tra " +
                    describePosition(c.ex.at, Language::It) + " e " +
                    describePosition(c.ex.until.value_or(ReplayPosition{ReplayPosition::Mode::End}),
                                     Language::It) +
                    ".");
            break;
        }
        case ExerciseKind::HitOrMiss: {
            const auto t = nextEvent<PrimitiveTest>(log, c.at);
            if (!t) c.fail("no primitive test follows its position");
            a.hit = t->second.hit;
            if (t->second.hit && c.ex.withT) a.numbers.push_back(t->second.t);
            const std::string prim = std::to_string(t->second.prim);
            why = t->second.hit
                      ? tr2(lang,
                            "The test of primitive " + prim + " hits at t = " + fmt(t->second.t) +
                                " (the smallest root inside the ray's interval).",
                            "Il test della primitiva " + prim +
                                " colpisce a t = " + fmt(t->second.t) +
                                " (la radice più piccola nell'intervallo del raggio).")
                      : tr2(lang,
                            "The test of primitive " + prim +
                                " misses: no root lies inside the ray's interval (a negative "
                                "discriminant, a root behind the origin or beyond the nearest "
                                "hit, or a point outside the triangle or segment).",
                            "Il test della primitiva " + prim +
                                " fallisce: nessuna radice cade nell'intervallo del raggio "
                                "(discriminante negativo, radice dietro l'origine o oltre il "
                                "colpo più vicino, o punto fuori dal triangolo o segmento).");
            break;
        }
    }
    return {a, why};
}

}  // namespace

std::optional<Answer> parseAnswer(const Exercise& ex, std::string_view text, std::string* why) {
    const auto bad = [&](const std::string& message) -> std::optional<Answer> {
        if (why) *why = message;
        return std::nullopt;
    };
    Answer a;
    switch (ex.kind) {
        case ExerciseKind::NextCell: {
            std::string_view s = text;
            const auto parts = splitAny(s, "(), ;\t");
            if (parts.size() < 2 || parts.size() > 3)
                return bad("expected a cell as X,Y or X,Y,Z (whole numbers)");
            for (const auto p : parts) {
                const auto v = parseNumber(p);
                if (!v || *v != std::floor(*v)) return bad("cell indices are whole numbers");
                a.numbers.push_back(*v);
            }
            return a;
        }
        case ExerciseKind::Value:
        case ExerciseKind::Count: {
            const auto v = parseNumber(text);
            if (!v) return bad("expected a number");
            if (ex.kind == ExerciseKind::Count && (*v < 0 || *v != std::floor(*v)))
                return bad("a count is a whole number, 0 or more");
            a.numbers.push_back(*v);
            return a;
        }
        case ExerciseKind::PickSplit: {
            const std::string s = lower(text);
            const auto eq = s.find('=');
            if (eq == std::string::npos)
                return bad("expected a split plane as x=POSITION (or y=, z=)");
            const auto axisPart = splitAny(std::string_view(s).substr(0, eq), " \t");
            if (axisPart.size() != 1 || axisPart[0].size() != 1 ||
                std::string_view("xyz").find(axisPart[0][0]) == std::string_view::npos)
                return bad("the axis is x, y or z");
            const auto v = parseNumber(std::string_view(s).substr(eq + 1));
            if (!v) return bad("expected a number after '='");
            a.numbers = {static_cast<double>(axisPart[0][0] - 'x'), *v};
            return a;
        }
        case ExerciseKind::HitOrMiss: {
            const std::string s = lower(text);
            const auto parts = splitAny(s, " \t=:");
            if (parts.empty()) return bad("expected \"hit\" (with its t) or \"miss\"");
            const std::string_view word = parts[0];
            if (word == "miss" || word == "manca" || word == "false") {
                if (parts.size() > 1) return bad("a miss has no t");
                a.hit = false;
                return a;
            }
            if (word != "hit" && word != "colpisce" && word != "true")
                return bad("expected \"hit\" (with its t) or \"miss\"");
            a.hit = true;
            std::size_t i = 1;
            if (i < parts.size() && parts[i] == "t") ++i;
            if (i < parts.size()) {
                const auto v = parseNumber(parts[i]);
                if (!v || i + 1 != parts.size()) return bad("expected \"hit T\" with T a number");
                a.numbers.push_back(*v);
            }
            if (ex.withT && a.numbers.empty()) return bad("give the hit's t too: \"hit T\"");
            return a;
        }
    }
    return bad("unknown exercise kind");
}

std::string formatAnswer(const Exercise& ex, const Answer& a) {
    switch (ex.kind) {
        case ExerciseKind::NextCell: {
            std::string s;
            for (std::size_t i = 0; i < a.numbers.size(); ++i)
                s += (i ? "," : "") + std::to_string(static_cast<long long>(a.numbers[i]));
            return s;
        }
        case ExerciseKind::Value:
            return a.numbers.empty() ? "" : fmt(a.numbers[0]);
        case ExerciseKind::Count:
            return a.numbers.empty() ? "" : std::to_string(static_cast<long long>(a.numbers[0]));
        case ExerciseKind::PickSplit:
            return a.numbers.size() < 2 ? ""
                                        : std::string(axisName(static_cast<int>(a.numbers[0]))) +
                                              "=" + fmt(a.numbers[1]);
        case ExerciseKind::HitOrMiss:
            if (!a.hit) return "";
            if (!*a.hit) return "miss";
            return a.numbers.empty() ? "hit" : "hit " + fmt(a.numbers[0]);
    }
    return "";
}

std::vector<SplitCandidate> splitCandidates(const Exercise& ex, const EventLog& log) {
    std::vector<SplitCandidate> out;
    const auto at = resolvePosition(ex.at, log);
    if (!at) return out;
    const auto node = nextEvent<BuildNode>(log, *at);
    if (!node) return out;
    for (const Event& e : log.events())
        if (const auto* s = std::get_if<SplitCandidate>(&e); s && s->node == node->second.node)
            out.push_back(*s);
    return out;
}

Answer referenceAnswer(const Exercise& ex, const EventLog& log, const std::string& lessonFile) {
    return reference(contextOf(ex, log, lessonFile), Language::En).first;
}

Verdict checkAnswer(const Exercise& ex, const EventLog& log, const Answer& answer, Language lang,
                    const std::string& lessonFile) {
    const Context c = contextOf(ex, log, lessonFile);
    const auto [ref, why] = reference(c, lang);
    Verdict v;
    v.expected = formatAnswer(ex, ref);
    v.feedback = why;
    switch (ex.kind) {
        case ExerciseKind::NextCell:
        case ExerciseKind::Count:
            v.correct = answer.numbers == ref.numbers;
            break;
        case ExerciseKind::Value:
            v.correct = answer.numbers.size() == 1 &&
                        close(answer.numbers[0], ref.numbers[0], ex.tolerance);
            break;
        case ExerciseKind::PickSplit: {
            // Any candidate as cheap as the cheapest is right (ties happen on symmetric scenes).
            if (answer.numbers.size() != 2) break;
            const double bestCost = [&] {
                double best = kInfinity;
                for (const SplitCandidate& s : splitCandidates(ex, log))
                    best = std::min(best, s.sahCost);
                return best;
            }();
            for (const SplitCandidate& s : splitCandidates(ex, log))
                if (s.axis == answer.numbers[0] && close(answer.numbers[1], s.position, 1e-9) &&
                    s.sahCost <= bestCost * (1.0 + 1e-12))
                    v.correct = true;
            break;
        }
        case ExerciseKind::HitOrMiss:
            v.correct =
                answer.hit == ref.hit && (!ex.withT || !*ref.hit ||
                                          (answer.numbers.size() == 1 &&
                                           close(answer.numbers[0], ref.numbers[0], ex.tolerance)));
            break;
    }
    return v;
}

void validateLesson(const Lesson& lesson) {
    const LessonRun run = runLesson(lesson);
    if (run.log->events().empty())
        throw LessonError(lesson.file, 0, "trace", "the trace recorded no events");
    for (const LessonStep& s : lesson.steps)
        if (!resolvePosition(s.at, *run.log))
            throw LessonError(lesson.file, s.line, "steps",
                              "its position (" + describePosition(s.at) + ") is not in the trace");
    for (const Exercise& ex : lesson.exercises) referenceAnswer(ex, *run.log, lesson.file);
    const bool is2D = std::holds_alternative<Scene2D>(*run.scene);
    for (const LessonView v : lesson.views)
        if ((v == LessonView::View2D) != is2D)
            throw LessonError(lesson.file, 0, "views",
                              std::string(nameOf(kViews, v)) + " does not fit a " +
                                  (is2D ? "2D" : "3D") + " scene");
}

// ---- answer sheets ----

namespace {
AnswerSheet readAnswerSheet(std::string_view text, const std::string& fileName) {
    auto parsed = detail::parseJsonFile<LessonError>(text, fileName);
    const json& root = parsed.root;
    const Reader r(fileName, std::move(parsed.lines));
    r.requireObject(root, "");
    r.checkKeys(root, "", {"lesson", "student", "answers"});
    if (!root.contains("lesson") || !root.contains("answers"))
        r.fail("", "an answers file holds {\"lesson\": ID, \"answers\": {EXERCISE: ANSWER}}");
    AnswerSheet sheet;
    // The id or the number (docs/lesson-format.md, "Answers files").
    const json& lesson = root["lesson"];
    if (lesson.is_number())
        sheet.lesson = std::to_string(r.integer(lesson, "lesson", 1, 999));
    else if (lesson.is_string())
        sheet.lesson = lesson.get<std::string>();
    else
        r.fail("lesson", "expected the lesson's id or number, got " + Reader::typeName(lesson));
    sheet.lessonLine = r.lines().lineOf("lesson");
    ifPresent(root, "", "student", [&](const json& v, const std::string& p) {
        if (!v.is_string() && !v.is_number())
            r.fail(p, "expected the student's name or number, got " + Reader::typeName(v));
    });
    r.requireObject(root["answers"], "answers");
    for (const auto& [id, v] : root["answers"].items()) {
        const std::string p = JsonLineMap::child("answers", id);
        std::string t;
        if (v.is_string()) {
            t = v.get<std::string>();
        } else if (v.is_boolean()) {
            t = v.get<bool>() ? "hit" : "miss";
        } else if (v.is_number()) {
            std::ostringstream s;
            s.precision(17);
            s << r.number(v, p);  // finite, checked
            t = s.str();
        } else if (v.is_array()) {
            for (std::size_t i = 0; i < v.size(); ++i) {
                std::ostringstream s;
                s.precision(17);
                s << r.number(v[i], JsonLineMap::element(p, i));
                t += (i ? "," : "") + s.str();
            }
        } else {
            r.fail(p, "expected a number, a list of numbers, a string or true/false");
        }
        sheet.answers[id] = t;
        sheet.lines[id] = r.lines().lineOf(p);
    }
    return sheet;
}
}  // namespace

AnswerSheet loadAnswerSheet(std::string_view text, const std::string& fileName) {
    return detail::guarded<LessonError>(fileName, [&] { return readAnswerSheet(text, fileName); });
}

AnswerSheet loadAnswerSheetFile(const std::string& path) {
    return loadAnswerSheet(readLessonFile(path, "answers file"), path);
}

Grade gradeAnswers(const Lesson& lesson, const EventLog& log, const AnswerSheet& sheet,
                   Language lang, const std::string& sheetFile) {
    if (sheet.lesson != lesson.id && sheet.lesson != std::to_string(lesson.number))
        throw LessonError(sheetFile, sheet.lessonLine, "lesson",
                          "the answers are for lesson '" + printable(sheet.lesson) + "', not '" +
                              lesson.id + "'");
    for (const auto& [id, text] : sheet.answers)
        if (!lesson.exercise(id))
            throw LessonError(sheetFile, sheet.lines.at(id), "answers." + id,
                              "lesson " + lesson.id + " has no exercise of that id");
    Grade g;
    for (const Exercise& ex : lesson.exercises) {
        Grade::Item item;
        item.exercise = ex.id;
        // One check per exercise: an unanswered or unreadable answer is checked as empty, which
        // still gives the expected answer and its explanation.
        std::optional<Answer> given;
        std::string why;
        if (const auto it = sheet.answers.find(ex.id); it != sheet.answers.end()) {
            item.answered = true;
            item.given = it->second;
            given = parseAnswer(ex, it->second, &why);
        }
        const Verdict v = checkAnswer(ex, log, given.value_or(Answer{}), lang, lesson.file);
        item.correct = given.has_value() && v.correct;
        item.expected = v.expected;
        item.feedback = item.answered && !given ? why + ". " + v.feedback : v.feedback;
        g.score += item.correct;
        g.items.push_back(std::move(item));
    }
    return g;
}

// ---- progress ----

namespace {
Progress readProgress(std::string_view text, const std::string& fileName) {
    auto parsed = detail::parseJsonFile<LessonError>(text, fileName);
    const json& root = parsed.root;
    const Reader r(fileName, std::move(parsed.lines));
    r.requireObject(root, "");
    r.checkKeys(root, "", {"format", "version", "lessons"});
    if (root.value("format", json()) != "raystep-progress")
        r.fail("format", "not a raystep progress file");
    Progress p;
    ifPresent(root, "", "lessons", [&](const json& v, const std::string& path) {
        r.requireObject(v, path);
        for (const auto& [id, lj] : v.items()) {
            const std::string lp = JsonLineMap::child(path, id);
            r.requireObject(lj, lp);
            r.checkKeys(lj, lp, {"step", "exercises"});
            LessonProgress& lesson = p.lessons[id];
            ifPresent(lj, lp, "step", [&](const json& s, const std::string& sp) {
                lesson.step = r.integer(s, sp, 0, 10'000);
            });
            ifPresent(lj, lp, "exercises", [&](const json& ej, const std::string& ep) {
                r.requireObject(ej, ep);
                for (const auto& [eid, rec] : ej.items()) {
                    const std::string rp = JsonLineMap::child(ep, eid);
                    r.requireObject(rec, rp);
                    r.checkKeys(rec, rp, {"correct", "attempts", "answer"});
                    LessonProgress::ExerciseRecord& e = lesson.exercises[eid];
                    ifPresent(rec, rp, "correct", [&](const json& x, const std::string& xp) {
                        if (!x.is_boolean()) r.fail(xp, "expected true or false");
                        e.correct = x.get<bool>();
                    });
                    ifPresent(rec, rp, "attempts", [&](const json& x, const std::string& xp) {
                        e.attempts = r.integer(x, xp, 0, 1'000'000);
                    });
                    ifPresent(rec, rp, "answer", [&](const json& x, const std::string& xp) {
                        e.answer = r.string(x, xp);
                    });
                }
            });
        }
    });
    return p;
}
}  // namespace

Progress parseProgress(std::string_view text, const std::string& fileName) {
    return detail::guarded<LessonError>(fileName, [&] { return readProgress(text, fileName); });
}

std::optional<Progress> loadProgressFile(const std::string& path) {
    std::string text;
    try {
        text = detail::readRegularFile(path, detail::kMaxJsonFileBytes);
    } catch (const detail::ReadFailure& f) {
        if (f.missing()) return std::nullopt;
        throw LessonError(path, 0, "", std::string("cannot read the progress file: ") + f.what());
    }
    return parseProgress(text, path);
}

std::string progressToJson(const Progress& p) {
    json lessons = json::object();
    for (const auto& [id, l] : p.lessons) {
        json ex = json::object();
        for (const auto& [eid, e] : l.exercises)
            ex[eid] = {{"correct", e.correct}, {"attempts", e.attempts}, {"answer", e.answer}};
        lessons[id] = {{"step", l.step}, {"exercises", ex}};
    }
    const json root = {{"format", "raystep-progress"}, {"version", 1}, {"lessons", lessons}};
    return root.dump(2) + "\n";
}

std::string progressReport(const Progress& p, const std::vector<Lesson>& lessons, Language lang) {
    const bool it = lang == Language::It;
    std::ostringstream s;
    s << (it ? "# raystep: progressi\n\n" : "# raystep: progress\n\n");
    s << (it ? "| Lezione | Esercizi | Svolti | Corretti | Tentativi |\n"
             : "| Lesson | Exercises | Done | Right | Attempts |\n");
    s << "|---|---:|---:|---:|---:|\n";
    int total = 0, done = 0, right = 0;
    for (const Lesson& l : lessons) {
        int d = 0, r = 0, attempts = 0;
        if (const auto lp = p.lessons.find(l.id); lp != p.lessons.end())
            for (const Exercise& ex : l.exercises)
                if (const auto e = lp->second.exercises.find(ex.id);
                    e != lp->second.exercises.end()) {
                    d += e->second.attempts > 0;
                    r += e->second.correct;
                    attempts += e->second.attempts;
                }
        total += static_cast<int>(l.exercises.size());
        done += d;
        right += r;
        s << "| " << l.number << ". " << l.title.in(lang) << " | " << l.exercises.size() << " | "
          << d << " | " << r << " | " << attempts << " |\n";
    }
    s << "\n"
      << (it ? "Totale: " : "Total: ") << right << " / " << total
      << (it ? " esercizi corretti, " : " exercises right, ") << done
      << (it ? " svolti.\n" : " attempted.\n");
    return s.str();
}

// ---- the grid sweep ----

std::vector<GridSweepRow> runGridSweep(const std::variant<Scene, Scene2D>& scene,
                                       const GridSweepSpec& spec, const ProgressFn& progress) {
    std::vector<GridSweepRow> rows;
    const auto* s3 = std::get_if<Scene>(&scene);
    const auto* s2 = std::get_if<Scene2D>(&scene);
    for (std::size_t k = 0; k < spec.resolutions.size(); ++k) {
        if (progress && !progress(static_cast<double>(k) / spec.resolutions.size()))
            throw BuildCancelled();
        const int res = spec.resolutions[k];
        AccelOptions o;
        o.grid.res = std::array<int, 3>{res, res, s3 ? res : 1};
        GridSweepRow row;
        row.resolution = res;
        TraversalCounters c;
        std::uint64_t rays = 0;
        const auto t0 = std::chrono::steady_clock::now();
        std::chrono::steady_clock::time_point t1;
        if (s3) {
            const Accelerator accel = buildAccelerator(*s3, AccelKind::Grid, {}, o);
            t1 = std::chrono::steady_clock::now();
            const BuildSummary sum = summarize(accel);
            row.cells = sum.stats.nodes;
            row.references = sum.stats.references;
            for (int y = 0; y < spec.height; ++y)
                for (int x = 0; x < spec.width; ++x, ++rays)
                    intersect(accel,
                              s3->camera.generateRay(x + 0.5, y + 0.5, spec.width, spec.height), c);
        } else {
            // 2D: a fan of rays from the example ray's origin (or the scene's corner).
            const Accelerator2D accel = buildAccelerator2D(*s2, AccelKind::Grid, o);
            t1 = std::chrono::steady_clock::now();
            const BuildSummary sum = summarize(accel);
            row.cells = sum.stats.nodes;
            row.references = sum.stats.references;
            const Vec2 origin = s2->exampleRay ? s2->exampleRay->origin : s2->bounds().lo;
            const int n = spec.width * spec.height;
            for (int i = 0; i < n; ++i, ++rays) {
                const double a = 2.0 * kPi * (i + 0.5) / n;
                const Ray2 ray{origin, Vec2(std::cos(a), std::sin(a))};
                std::visit([&](const auto& g) { g.intersect(ray, c); }, accel);
            }
        }
        const auto t2 = std::chrono::steady_clock::now();
        row.buildMs = std::chrono::duration<double, std::milli>(t1 - t0).count();
        row.traceMs = std::chrono::duration<double, std::milli>(t2 - t1).count();
        row.testsPerRay = static_cast<double>(c.primitiveTests) / rays;
        row.cellsPerRay = static_cast<double>(c.nodeVisits) / rays;
        row.skipsPerRay = static_cast<double>(c.mailboxSkips) / rays;
        rows.push_back(row);
    }
    if (progress) progress(1.0);
    return rows;
}

void mergeProgress(Progress& into, const Progress& saved) {
    for (const auto& [id, theirs] : saved.lessons) {
        const auto [it, added] = into.lessons.try_emplace(id, theirs);
        if (added) continue;
        for (const auto& [ex, rec] : theirs.exercises) {
            const auto [mine, fresh] = it->second.exercises.try_emplace(ex, rec);
            if (fresh) continue;
            if (rec.attempts > mine->second.attempts) {
                mine->second.attempts = rec.attempts;
                mine->second.answer = rec.answer;
            }
            mine->second.correct = mine->second.correct || rec.correct;
        }
    }
}

}  // namespace raystep

// Reading lesson files (docs/lesson-format.md) into the model of course/lesson.h, with errors
// that name the file, the line and the key; and finding the built-in lessons.
#include "course/lesson.h"

#include "course/embedded_lessons.h"
#include "course/exercises/kind_unit.h"
#include "course/palette.h"
#include "course/practice/practice.h"

#include "raystep/base/format.h"
#include "raystep/base/json_reader.h"
#include "raystep/base/names.h"
#include "raystep/geometry/kernels.h"
#include "raystep/scene/scene_loader.h"
#include "raystep/trace/replay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace raystep {

using detail::ifPresent;
using detail::json;
using Reader = detail::JsonReader<LessonError>;

namespace {

constexpr NameTable<SweepMetric, 3> kSweepMetrics{{{SweepMetric::Cost, "cost"},
                                                   {SweepMetric::TestsPerRay, "tests_per_ray"},
                                                   {SweepMetric::CellsPerRay, "cells_per_ray"}}};
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
constexpr NameTable<LessonView, 4> kViews{{{LessonView::View2D, "2d"},
                                           {LessonView::View3D, "3d"},
                                           {LessonView::Image, "image"},
                                           {LessonView::Board, "board"}}};

}  // namespace

// What a kind's unit reads its keys with too (course/exercises/kind_unit.h).
namespace lesson_reading {

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

// ---- reading lesson files ----

/// One language's text: a string, or an array of lines (easier to write and review than one long
/// string), with its {colour:NAME}s replaced by the palette's name in `lang`.
std::string readOneText(const Reader& r, const json& v, const std::string& p, Language lang) {
    std::string s;
    if (v.is_string()) {
        s = v.get<std::string>();
    } else if (v.is_array()) {
        for (std::size_t i = 0; i < v.size(); ++i) {
            if (i) s += '\n';
            s += r.string(v[i], JsonLineMap::element(p, i));
        }
    } else {
        r.fail(p, "expected a string or an array of lines, got " + Reader::typeName(v));
    }
    std::string unknown;
    auto expanded = expandColourNames(s, lang, &unknown);
    if (!expanded) {
        std::string keys;
        for (const PaletteColour& c : paletteColours())
            keys += (keys.empty() ? "" : ", ") + std::string(c.key);
        r.fail(p, "unknown colour {colour:" + printable(unknown, 40) + "} (the palette has " +
                      keys + ")");
    }
    return std::move(*expanded);
}

/// TEXT: {"en": ..., "it": ..., CODE: ...}, a key per language of the registry (base/i18n.h);
/// with `plainAllowed`, also one string for every language (a slide's line, quoted as written).
LocalText readText(const Reader& r, const json& j, const std::string& path, bool plainAllowed) {
    const std::vector<Language> all = languages();
    if (plainAllowed && (j.is_string() || j.is_array())) {
        LocalText t;
        for (const Language lang : all) t.set(lang, readOneText(r, j, path, lang));
        if (t.en.empty()) r.fail(path, "must not be empty");
        return t;
    }
    r.requireObject(j, path);
    for (const auto& [key, value] : j.items())
        if (!parseLanguage(key)) {
            std::string codes;
            for (const Language lang : all) {
                codes += codes.empty() ? "" : ", ";
                codes += lang.code();
            }
            r.fail(JsonLineMap::child(path, key), "unknown key (allowed here: " + codes + ")");
        }
    if (!j.contains("en")) r.fail(path, "the English text \"en\" is required");
    LocalText t;
    for (const Language lang : all) {
        const std::string code(lang.code());
        ifPresent(j, path, code.c_str(), [&](const json& v, const std::string& p) {
            t.set(lang, readOneText(r, v, p, lang));
        });
    }
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

}  // namespace lesson_reading

using lesson_reading::readPosition;
using lesson_reading::readText;

namespace {

/// "hint": one TEXT, or an array of TEXTs shown one at a time.
std::vector<LocalText> readHints(const Reader& r, const json& j, const std::string& path) {
    std::vector<LocalText> hints;
    if (j.is_array()) {
        if (j.empty()) r.fail(path, "expected a hint {\"en\": ..., \"it\": ...} or a list of them");
        for (std::size_t i = 0; i < j.size(); ++i)
            hints.push_back(readText(r, j[i], JsonLineMap::element(path, i)));
    } else {
        hints.push_back(readText(r, j, path));
    }
    return hints;
}

/// "errata": [{"slide": TEXT, "correct": TEXT, "why": TEXT}, ...].
std::vector<Erratum> readErrata(const Reader& r, const json& j, const std::string& path) {
    if (!j.is_array())
        r.fail(path, "expected a list of {\"slide\": ..., \"correct\": ..., \"why\": ...}");
    std::vector<Erratum> errata;
    for (std::size_t i = 0; i < j.size(); ++i) {
        const std::string p = JsonLineMap::element(path, i);
        r.requireObject(j[i], p);
        r.checkKeys(j[i], p, {"slide", "correct", "why"});
        for (const char* key : {"slide", "correct", "why"})
            if (!j[i].contains(key)) r.fail(p, std::string("\"") + key + "\" is required");
        Erratum e;
        e.line = r.lines().lineOf(p);
        // The slide is quoted as written: its Italian original may stand for both languages.
        e.slide = readText(r, j[i]["slide"], JsonLineMap::child(p, "slide"), true);
        e.correct = readText(r, j[i]["correct"], JsonLineMap::child(p, "correct"), true);
        e.why = readText(r, j[i]["why"], JsonLineMap::child(p, "why"));
        errata.push_back(std::move(e));
    }
    return errata;
}

/// "setup": its keys over `l` (the lesson's setup, or a copy of it for a step or an exercise).
void readSetup(const Reader& r, const json& j, const std::string& path, LessonSetup& l) {
    r.requireObject(j, path);
    // The keys: "accel" and every option of the structures' table (structure_info.h).
    std::string allowed = "accel";
    for (const OptionInfo& o : accelOptions()) allowed += ", " + std::string(o.key);
    for (const auto& [key, value] : j.items()) {
        bool known = key == "accel";
        for (const OptionInfo& o : accelOptions()) known = known || key == o.key;
        if (!known)
            r.fail(JsonLineMap::child(path, key), "unknown key (allowed here: " + allowed + ")");
    }
    AccelOptions& o = l.options;
    ifPresent(j, path, "accel", [&](const json& v, const std::string& p) {
        const auto k = parseAccelKind(r.string(v, p));
        if (!k) r.fail(p, "expected " + kindList());
        l.accel = *k;
    });
    for (const OptionInfo& info : accelOptions()) {
        const std::string key(info.key);
        ifPresent(j, path, key.c_str(), [&](const json& v, const std::string& p) {
            switch (info.type) {
                case OptionType::Choice:
                    if (info.option == AccelOption::Split) {
                        const auto s = parseSplitMethod(r.string(v, p));
                        if (!s) r.fail(p, "expected midpoint, median or sah");
                        o.setSplit(*s);
                    } else {
                        const auto b = parseKdBuild(r.string(v, p));
                        if (!b) r.fail(p, "expected exact or fast");
                        o.kdtree.build = *b;
                    }
                    return;
                case OptionType::Switch:
                    if (!v.is_boolean())
                        r.fail(p, "expected true or false, got " + Reader::typeName(v));
                    o.set(info.option, v.get<bool>());
                    return;
                case OptionType::Cells: {
                    if (!v.is_array() || v.size() < 2 || v.size() > 3)
                        r.fail(p, "expected [NX, NY] or [NX, NY, NZ], got " + Reader::typeName(v));
                    std::array<int, 3> res{1, 1, 1};
                    for (std::size_t i = 0; i < v.size(); ++i)
                        res[i] =
                            r.integer(v[i], JsonLineMap::element(p, i), int(info.lo), int(info.hi));
                    const std::size_t cells = std::size_t(res[0]) * res[1] * res[2];
                    if (cells > GridOptions::kMaxCells)
                        r.fail(p, std::to_string(cells) + " cells, more than the grid's " +
                                      std::to_string(GridOptions::kMaxCells) + " (2^24)");
                    o.grid.res = res;
                    return;
                }
                case OptionType::Number:
                case OptionType::Whole: {
                    const double x = r.number(v, p);
                    if (auto why = optionProblem(info.option, x))
                        r.fail(p, *why + ", got " + formatNumber(x));
                    o.set(info.option, x);
                    return;
                }
            }
        });
    }
    if (o.kdtree.build == KdBuild::Fast && j.contains("bin_above"))
        r.fail(JsonLineMap::child(path, "bin_above"),
               "the fast build (kd_build) bins every node already");
}

/// A step's or an exercise's own "setup": the lesson's with these keys over it.
std::optional<LessonSetup> readOwnSetup(const Reader& r, const json& j, const std::string& path,
                                        const LessonSetup& lesson) {
    std::optional<LessonSetup> own;
    ifPresent(j, path, "setup", [&](const json& v, const std::string& p) {
        LessonSetup s = lesson;
        readSetup(r, v, p, s);
        own = std::move(s);
    });
    return own;
}

/// "compare": {"accel": "grid,kdtree,bvh", "split": "sah"}, read as the CLI's compare reads them.
std::vector<StructureChoice> readCompare(const Reader& r, const json& j, const std::string& path) {
    r.requireObject(j, path);
    r.checkKeys(j, path, {"accel", "split"});
    const std::string ap = JsonLineMap::child(path, "accel"),
                      sp = JsonLineMap::child(path, "split");
    if (!j.contains("accel")) r.fail(path, "\"accel\" is required: \"grid,kdtree,bvh\"");
    const std::string kinds = r.string(j["accel"], ap);
    std::optional<std::string> splits;
    ifPresent(j, path, "split",
              [&](const json& v, const std::string& p) { splits = r.string(v, p); });
    auto parsed = parseStructureChoices(kinds, splits, "accel", "split");
    if (auto* why = std::get_if<std::string>(&parsed))
        // The message names the key it refuses; the line is that key's.
        r.fail(splits && why->find("split") != std::string::npos ? sp : ap, *why);
    return std::get<std::vector<StructureChoice>>(std::move(parsed));
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
            if (v.is_array() && v.size() == 6) {
                double n[6];
                for (int i = 0; i < 6; ++i) n[i] = r.number(v[i], JsonLineMap::element(p, i));
                const double o = std::max({std::abs(n[0]), std::abs(n[1]), std::abs(n[2])});
                const double d = std::max({std::abs(n[3]), std::abs(n[4]), std::abs(n[5])});
                if (d == 0.0) r.fail(p, "the direction must not be zero");
                if (const auto problem = rayRangeProblem(Precision::Double, o, d))
                    r.fail(p, *problem);
                t.kind = LessonTrace::Kind::Ray3D;
                t.ray3D = Ray{Vec3(n[0], n[1], n[2]), Vec3(n[3], n[4], n[5])};
                return;
            }
            if (!v.is_array() || v.size() != 4)
                r.fail(p, "expected \"example\", [OX, OY, DX, DY] or [OX, OY, OZ, DX, DY, DZ]");
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

/// Every kind's own keys, each once, with the first kind (in the registry's order) that takes it.
const std::vector<std::pair<const char*, std::string_view>>& kindKeys() {
    static const auto keys = [] {
        std::vector<std::pair<const char*, std::string_view>> out;
        for (const exercises::ExerciseKindUnit* u : exercises::kindUnits())
            for (const char* key : u->keys())
                if (std::none_of(out.begin(), out.end(),
                                 [&](const auto& k) { return std::string_view(k.first) == key; }))
                    out.emplace_back(key, u->name());
        return out;
    }();
    return keys;
}

Exercise readExercise(const Reader& r, const json& j, const std::string& path,
                      const LessonSetup& lessonSetup) {
    r.requireObject(j, path);
    // The keys every exercise takes, then each kind's own.
    std::vector<std::string> allowed{"id", "type", "at", "prompt", "hint", "tolerance", "setup"};
    for (const auto& [key, owner] : kindKeys()) allowed.emplace_back(key);
    for (const auto& [key, value] : j.items())
        if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
            std::string names;
            for (const std::string& a : allowed) names += (names.empty() ? "" : ", ") + a;
            r.fail(JsonLineMap::child(path, key), "unknown key (allowed here: " + names + ")");
        }
    Exercise ex;
    ex.line = r.lines().lineOf(path);
    ex.setup = readOwnSetup(r, j, path, lessonSetup);
    for (const char* key : {"id", "type", "prompt"})
        if (!j.contains(key)) r.fail(path, std::string("\"") + key + "\" is required");
    ex.id = r.string(j["id"], JsonLineMap::child(path, "id"));
    if (ex.id.empty() || ex.id.find_first_of(" \t\n\"") != std::string::npos)
        r.fail(JsonLineMap::child(path, "id"), "an exercise id is one word, e.g. \"next-cell\"");
    const std::string typePath = JsonLineMap::child(path, "type");
    const std::string type = r.string(j["type"], typePath);
    const exercises::ExerciseKindUnit* kind = nullptr;
    std::string kinds;
    const auto& units = exercises::kindUnits();
    for (std::size_t k = 0; k < units.size(); ++k) {
        if (units[k]->name() == type) kind = units[k];
        kinds += (k == 0                  ? ""
                  : k + 1 == units.size() ? " or "
                                          : ", ") +
                 std::string(units[k]->name());
    }
    if (!kind) r.fail(typePath, "expected " + kinds);
    ex.kind = kind->kind();
    ex.prompt = readText(r, j["prompt"], JsonLineMap::child(path, "prompt"));
    ifPresent(j, path, "hint",
              [&](const json& v, const std::string& p) { ex.hints = readHints(r, v, p); });
    ifPresent(j, path, "at",
              [&](const json& v, const std::string& p) { ex.at = readPosition(r, v, p); });
    ifPresent(j, path, "tolerance", [&](const json& v, const std::string& p) {
        ex.tolerance = r.positive(v, p);
        if (ex.tolerance >= 1.0) r.fail(p, "a tolerance of 100% or more accepts anything");
    });
    // A kind's own keys: a kind that does not take one names the first kind that does.
    const exercises::ExerciseKindUnit& unit = exercises::unitOf(ex.kind);
    for (const auto& entry : kindKeys()) {
        // Named, not a structured binding: clang 14 cannot capture a binding in a lambda.
        const auto& key = entry.first;
        const auto& owner = entry.second;
        const auto own = unit.keys();
        const auto takes = [&](const char* k) { return std::string_view(k) == key; };
        if (j.contains(key) && std::none_of(own.begin(), own.end(), takes))
            r.fail(JsonLineMap::child(path, key),
                   "only " + std::string(owner) + " exercises take this key");
    }
    unit.read(r, j, path, ex);
    return ex;
}

LessonStep readStep(const Reader& r, const json& j, const std::string& path,
                    const LessonSetup& lessonSetup) {
    r.requireObject(j, path);
    r.checkKeys(j, path,
                {"text", "at", "filter", "camera", "textbook_dda", "errata", "setup", "compare"});
    LessonStep s;
    s.line = r.lines().lineOf(path);
    s.setup = readOwnSetup(r, j, path, lessonSetup);
    ifPresent(j, path, "compare",
              [&](const json& v, const std::string& p) { s.compare = readCompare(r, v, p); });
    if (!j.contains("text")) r.fail(path, "a step needs its \"text\"");
    s.text = readText(r, j["text"], JsonLineMap::child(path, "text"));
    ifPresent(j, path, "at",
              [&](const json& v, const std::string& p) { s.at = readPosition(r, v, p); });
    ifPresent(j, path, "filter",
              [&](const json& v, const std::string& p) { s.filter = r.string(v, p); });
    ifPresent(j, path, "errata",
              [&](const json& v, const std::string& p) { s.errata = readErrata(r, v, p); });
    ifPresent(j, path, "textbook_dda", [&](const json& v, const std::string& p) {
        if (!v.is_boolean()) r.fail(p, "expected true or false");
        s.textbookDda = v.get<bool>();
    });
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

// Built-in lessons are named by their place in the source tree, as a lesson file would be.
constexpr std::string_view kLessonFolder = "lessons/";

}  // namespace

std::string erratumHeading(Language lang) {
    return tr(lang, "Note on the slides");
}

const std::string& LocalText::slot(Language l) const {
    static const std::string none;
    if (l == Language::En) return en;
    const auto found = other.find(l.code());
    return found == other.end() ? none : found->second;
}

const std::string& LocalText::in(Language l) const {
    const std::string& s = slot(l);
    return s.empty() ? en : s;
}

void LocalText::set(Language l, std::string text) {
    if (l == Language::En)
        en = std::move(text);
    else
        other[std::string(l.code())] = std::move(text);
}

std::string_view exerciseKindName(ExerciseKind k) {
    return exercises::unitOf(k).name();
}
std::optional<Quantity> parseQuantity(std::string_view name) {
    return valueNamed(kQuantities, name);
}
std::string_view sweepMetricName(SweepMetric m) {
    return nameOf(kSweepMetrics, m);
}
std::string_view quantityName(Quantity q) {
    return nameOf(kQuantities, q);
}
std::string_view lessonViewName(LessonView v) {
    return nameOf(kViews, v);
}

std::string LessonSetup::key() const {
    std::string k(accelKindName(accel));
    const std::optional<SplitMethod> split = options.split(accel);
    for (const OptionInfo& info : accelOptions()) {
        if (!readsOption(accel, info.option, split.value_or(SplitMethod::Midpoint))) continue;
        if (info.option == AccelOption::GridRes) {
            if (!options.grid.res) k += " res=auto";
            if (options.grid.res)
                for (const int n : *options.grid.res) k += " " + std::to_string(n);
            continue;
        }
        char v[32];  // every digit: two setups differ if any option does
        std::snprintf(v, sizeof v, "%.17g", options.value(accel, info.option));
        k += " " + std::string(info.key) + "=" + v;
    }
    // A replayed walk is a trace of its own, though its structure is the lesson's.
    if (!replay.empty()) k += " replay=" + replay;
    return k;
}

std::string LessonSetup::name() const {
    return choiceName({accel, options.split(accel)});
}

std::vector<LessonSetup> Lesson::setups() const {
    std::vector<LessonSetup> out{setup()};
    const auto add = [&](const std::optional<LessonSetup>& s) {
        if (s && std::none_of(out.begin(), out.end(),
                              [&](const LessonSetup& o) { return o.key() == s->key(); }))
            out.push_back(*s);
    };
    for (const LessonStep& s : steps) add(s.setup);
    for (const Exercise& e : exercises) add(e.setup);
    return out;
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
                 "trace", "sweep", "steps", "exercises", "errata"});
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
    ifPresent(root, "", "errata",
              [&](const json& v, const std::string& p) { l.errata = readErrata(r, v, p); });
    if (root["scene"].is_object()) {
        // An inline scene is read here, so its errors name the lesson file and its key.
        l.sceneText = root["scene"].dump();
        l.scene = "(inline scene)";
        try {
            if (isScene2DText(l.sceneText))
                loadScene2DText(l.sceneText, "scene");
            else
                loadSceneText(l.sceneText, "scene",
                              [](const std::string&) { return std::nullopt; });
        } catch (const SceneError& e) {
            // The scene's key under the lesson's "scene", on the lesson file's own line.
            std::string message = e.what();
            const std::string lead =
                e.key().empty() ? ": " : "key '" + printable(e.key(), 160) + "': ";
            if (const auto at = message.find(lead); at != std::string::npos)
                message = message.substr(at + lead.size());
            r.fail(e.key().empty() ? std::string("scene") : "scene." + e.key(), message);
        }
    } else {
        l.scene = r.string(root["scene"], "scene");
        if (l.scene.empty())
            r.fail("scene", "must name a built-in scene or a scene file, or hold one");
    }
    LessonSetup setup;
    ifPresent(root, "", "setup",
              [&](const json& v, const std::string& p) { readSetup(r, v, p, setup); });
    l.accel = setup.accel;
    l.options = setup.options;
    readTrace(r, root["trace"], "trace", l.trace);
    ifPresent(root, "", "views", [&](const json& v, const std::string& p) {
        if (!v.is_array() || v.empty())
            r.fail(p, "expected a list of views: \"2d\", \"3d\", \"image\", \"board\"");
        for (std::size_t i = 0; i < v.size(); ++i) {
            const std::string ep = JsonLineMap::element(p, i);
            const auto view = valueNamed(kViews, r.string(v[i], ep));
            if (!view) r.fail(ep, "expected \"2d\", \"3d\", \"image\" or \"board\"");
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
            l.steps.push_back(readStep(r, v[i], JsonLineMap::element(p, i), setup));
    });
    ifPresent(root, "", "exercises", [&](const json& v, const std::string& p) {
        if (!v.is_array()) r.fail(p, "expected an array of exercises");
        for (std::size_t i = 0; i < v.size(); ++i) {
            const std::string ep = JsonLineMap::element(p, i);
            Exercise ex = readExercise(r, v[i], ep, setup);
            if (l.exercise(ex.id)) r.fail(JsonLineMap::child(ep, "id"), "exercise id used twice");
            l.exercises.push_back(std::move(ex));
        }
    });
    const bool twoDTrace =
        l.trace.kind == LessonTrace::Kind::ExampleRay || l.trace.kind == LessonTrace::Kind::Ray2D;
    if (l.views.empty())
        l.views = twoDTrace ? std::vector<LessonView>{LessonView::View2D}
                            : std::vector<LessonView>{LessonView::View3D, LessonView::Image};
    for (Exercise& ex : l.exercises) {
        // A node's SAH cost is the exercise's structure's: its costs, as the kd-tree build uses.
        const AccelOptions o = l.setupOf(ex.setup).options;
        ex.given.cTrav = o.kdtree.cTrav;
        ex.given.cIsect = o.kdtree.cIsect;
        ex.given.emptyBonus = o.kdtree.emptyBonus;
    }
    for (std::size_t i = 0; i < l.exercises.size(); ++i) {
        Exercise& ex = l.exercises[i];
        if (!exercises::unitOf(ex.kind).replaysOwnWalk()) continue;
        // Its wrong walk is a trace of its own, walked on its structure's grid.
        const std::string ep = JsonLineMap::element("exercises", i);
        LessonSetup own = l.setupOf(ex.setup);
        // A structure of cells: the one whose build reads grid_res (its row, structure_info.h).
        const auto hasCells = [](AccelKind k) { return readsOption(k, AccelOption::GridRes); };
        if (!hasCells(own.accel))
            r.fail(JsonLineMap::child(ep, ex.setup ? "setup" : "type"),
                   "a " + std::string(exerciseKindName(ex.kind)) +
                       " exercise replays a walk through cells: the lesson's setup.accel, or the "
                       "exercise's own, must be " +
                       kindList(+hasCells));
        if (!ex.walkRay && l.trace.kind == LessonTrace::Kind::Build)
            r.fail(ep, "a " + std::string(exerciseKindName(ex.kind)) +
                           " exercise on a lesson that records a build needs its own \"ray\"");
        own.replay = ex.id;
        ex.setup = own;
    }
    for (std::size_t i = 0; i < l.exercises.size(); ++i)
        if (exercises::unitOf(l.exercises[i].kind).needsSweep() && !l.sweep)
            r.fail(JsonLineMap::child(JsonLineMap::element("exercises", i), "type"),
                   "a " + std::string(exerciseKindName(l.exercises[i].kind)) +
                       " exercise needs the lesson's \"sweep\"");
    if (l.trace.kind == LessonTrace::Kind::Build && !recordsBuild(l.accel))
        r.fail("trace", "a build can be recorded for " + kindList(recordsBuild) + " (setup.accel)");
    // The trace is recorded through every structure named: a build needs one that records it.
    const auto ownBuild = [&](const std::optional<LessonSetup>& own, const std::string& at) {
        // A replayed walk records no build.
        if (l.trace.kind == LessonTrace::Kind::Build && own && own->replay.empty() &&
            !recordsBuild(own->accel))
            r.fail(JsonLineMap::child(JsonLineMap::child(at, "setup"), "accel"),
                   "the lesson records a build, which " + kindList(recordsBuild) + " have");
    };
    for (std::size_t i = 0; i < l.steps.size(); ++i)
        ownBuild(l.steps[i].setup, JsonLineMap::element("steps", i));
    for (std::size_t i = 0; i < l.exercises.size(); ++i)
        ownBuild(l.exercises[i].setup, JsonLineMap::element("exercises", i));
    return l;
}

}  // namespace

Lesson loadLessonText(std::string_view text, const std::string& fileName) {
    return detail::guarded<LessonError>(fileName, [&] { return readLesson(text, fileName); });
}

std::vector<Lesson> builtinLessons() {
    std::vector<Lesson> lessons;
    for (const std::string& f : embeddedLessonNames()) {
        lessons.push_back(loadLessonText(*embeddedLesson(f), std::string(kLessonFolder) + f));
        lessons.back().builtin = true;
    }
    std::sort(lessons.begin(), lessons.end(),
              [](const Lesson& a, const Lesson& b) { return a.number < b.number; });
    return lessons;
}

std::string lessonHeading(const Lesson& lesson, Language lang) {
    if (parsePracticeLessonId(lesson.id)) return lesson.title.in(lang);
    return std::to_string(lesson.number) + ". " + lesson.title.in(lang);
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
        // A practice's id made again from its topic, level and seed (a homework's sheets).
        if (const auto k = parsePracticeLessonId(idOrPath)) {
            try {
                return makePractice(k->topic, k->seed, k->level).lesson;
            } catch (const std::logic_error& e) {
                // A generator that finds no valid draw is a bug, yet one line, never a crash.
                throw LessonError(idOrPath, 0, "", e.what());
            }
        }
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

}  // namespace raystep

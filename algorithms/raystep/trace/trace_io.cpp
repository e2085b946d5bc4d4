#include "raystep/trace/trace_io.h"

#include "raystep/base/json_lines.h"
#include "raystep/base/json_reader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace raystep {

using nlohmann::ordered_json;

namespace {

/// A field added to version 1 after its first files: always written, read when present (a trace
/// written before it still reads; readEvent says what stands in, readTrace fills it in).
template <typename T>
struct Added {
    T& v;
};
template <typename T>
constexpr bool kAdded = false;
template <typename T>
constexpr bool kAdded<Added<T>> = true;

// Each event's fields, named once: the writer and the reader both walk this list, so the file
// and the structs cannot drift apart.
template <typename F>
void fields(RayBegin& e, F&& f) {
    f("ray", e.ray), f("parent", e.parent), f("kind", e.kind), f("depth", e.depth);
}
template <typename F>
void fields(DdaSetup& e, F&& f) {
    f("ray", e.ray), f("dims", e.dims), f("step", e.step), f("tDelta", e.tDelta);
    f("t_enter", e.tEnter), f("t_exit", e.tGridExit);
}
template <typename F>
void fields(DdaCell& e, F&& f) {
    f("ray", e.ray), f("axes", e.axes), f("cell", e.cell), f("tMax", e.tMax);
}
template <typename F>
void fields(MailboxSkip& e, F&& f) {
    f("ray", e.ray), f("prim", e.prim);
}
template <typename F>
void fields(PrimitiveTest& e, F&& f) {
    f("ray", e.ray), f("prim", e.prim), f("hit", e.hit), f("t", e.t);
}
template <typename F>
void fields(NodeEnter& e, F&& f) {
    f("ray", e.ray), f("node", e.node), f("t_near", e.tNear), f("t_far", e.tFar);
}
template <typename F>
void fields(NodeSkip& e, F&& f) {
    f("ray", e.ray), f("node", e.node), f("t_near", e.tNear), f("t_far", e.tFar);
}
template <typename F>
void fields(BuildNode& e, F&& f) {
    f("node", e.node), f("parent", e.parent), f("depth", e.depth), f("prims", e.prims);
    f("c_isect", Added<double>{e.cIsect}), f("leaf_cost", Added<double>{e.leafCost});
}
template <typename F>
void fields(SplitCandidate& e, F&& f) {
    f("node", e.node), f("axis", e.axis), f("position", e.position), f("nl", e.nl), f("nr", e.nr);
    f("pl", e.pl), f("pr", e.pr), f("sah_cost", e.sahCost);
}
template <typename F>
void fields(SplitChosen& e, F&& f) {
    f("node", e.node), f("axis", e.axis), f("position", e.position), f("sah_cost", e.sahCost);
    f("leaf_cost", e.leafCost);
}
template <typename F>
void fields(LeafMade& e, F&& f) {
    f("node", e.node), f("reason", e.reason), f("prims", e.prims), f("depth", e.depth);
    f("leaf_cost", e.leafCost);
}
template <typename F>
void fields(RayHit& e, F&& f) {
    f("ray", e.ray), f("prim", e.prim), f("t", e.t), f("u", e.u), f("v", e.v);
}
template <typename F>
void fields(RayMiss& e, F&& f) {
    f("ray", e.ray);
}
template <typename F>
void fields(ShadingTerm& e, F&& f) {
    f("ray", e.ray), f("term", e.term), f("light", e.light), f("rgb", e.rgb);
}
template <typename F>
void fields(RayBlocked& e, F&& f) {
    f("ray", e.ray), f("prim", e.prim), f("t", e.t);
}
template <typename F>
void fields(PixelResult& e, F&& f) {
    f("x", e.x), f("y", e.y), f("width", Added<std::uint32_t>{e.width});
    f("height", Added<std::uint32_t>{e.height}), f("rgb", e.rgb);
}

template <typename E, std::size_t N>
std::string_view enumName(const std::array<std::string_view, N>& names, E v) {
    return names[static_cast<std::size_t>(v)];
}

// Infinity has no JSON spelling: it is written as null (an empty interval end, a miss's t).
ordered_json number(double v) {
    if (std::isinf(v) && v > 0) return nullptr;
    if (std::isinf(v)) return "-inf";
    return v;
}
// kNoId (no parent, no light, no primitive) is written as null.
ordered_json id(std::uint32_t v) {
    return v == kNoId ? ordered_json(nullptr) : ordered_json(v);
}

struct Writer {
    ordered_json& j;
    template <typename T>
    void operator()(const char* key, const T& v) {
        if constexpr (kAdded<T>) {
            // Not recorded (an old trace's, read): left out, so it reads back as not recorded.
            if constexpr (std::is_same_v<T, Added<double>>)
                if (std::isnan(v.v)) return;
            (*this)(key, v.v);
        } else if constexpr (std::is_same_v<T, RayKind>)
            j[key] = enumName(kRayKindNames, v);
        else if constexpr (std::is_same_v<T, LeafReason>)
            j[key] = enumName(kLeafReasonNames, v);
        else if constexpr (std::is_same_v<T, ShadingTermKind>)
            j[key] = enumName(kShadingTermNames, v);
        else if constexpr (std::is_same_v<T, bool>)
            j[key] = v;
        else if constexpr (std::is_same_v<T, double>)
            j[key] = number(v);
        else if constexpr (std::is_same_v<T, std::uint32_t>)
            j[key] = id(v);
        else if constexpr (std::is_integral_v<T>)
            j[key] = static_cast<int>(v);
        else {  // arrays
            ordered_json a = ordered_json::array();
            for (const auto& x : v) {
                if constexpr (std::is_same_v<std::decay_t<decltype(x)>, double>)
                    a.push_back(number(x));
                else
                    a.push_back(static_cast<int>(x));
            }
            j[key] = a;
        }
    }
};

class Reader {
  public:
    Reader(const std::string& file, JsonLineMap lines) : file_(file), lines_(std::move(lines)) {}

    [[noreturn]] void fail(const std::string& path, const std::string& message) const {
        throw TraceError(file_, lines_.lineOf(path), path, message);
    }
    void requireObject(const ordered_json& j, const std::string& path) const {
        if (!j.is_object()) fail(path, "expected an object");
    }
    const ordered_json& at(const ordered_json& obj, const std::string& path,
                           const char* key) const {
        requireObject(obj, path);
        const auto it = obj.find(key);
        if (it == obj.end()) fail(JsonLineMap::child(path, key), "missing");
        return *it;
    }
    double number(const ordered_json& j, const std::string& path) const {
        if (j.is_null()) return kInfinity;
        if (j.is_string() && j.get<std::string>() == "-inf") return -kInfinity;
        if (!j.is_number()) fail(path, "expected a number (or null for infinity)");
        const double v = j.get<double>();
        if (!std::isfinite(v)) fail(path, "must be finite (write null for infinity)");
        return v;
    }
    std::int64_t integer(const ordered_json& j, const std::string& path, std::int64_t lo,
                         std::int64_t hi) const {
        if (!j.is_number_integer())
            fail(path, "expected a whole number from " + std::to_string(lo) + " to " +
                           std::to_string(hi));
        // An unsigned value past int64's range would wrap in get<std::int64_t>().
        if (j.is_number_unsigned() &&
            j.get<std::uint64_t>() >
                static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
            fail(path, "must be from " + std::to_string(lo) + " to " + std::to_string(hi));
        const auto v = j.get<std::int64_t>();
        if (v < lo || v > hi)
            fail(path, "must be from " + std::to_string(lo) + " to " + std::to_string(hi));
        return v;
    }
    std::uint32_t idValue(const ordered_json& j, const std::string& path) const {
        if (j.is_null()) return kNoId;
        return static_cast<std::uint32_t>(integer(j, path, 0, kNoId - 1));
    }
    std::string string(const ordered_json& j, const std::string& path) const {
        if (!j.is_string()) fail(path, "expected a string");
        return j.get<std::string>();
    }
    template <typename E, std::size_t N>
    E enumValue(const std::array<std::string_view, N>& names, const ordered_json& j,
                const std::string& path) const {
        if (j.is_string())
            for (std::size_t i = 0; i < N; ++i)
                if (names[i] == j.get<std::string>()) return static_cast<E>(i);
        std::string all;
        for (auto n : names) all += (all.empty() ? "" : ", ") + std::string(n);
        fail(path, "expected one of: " + all);
    }
    /// An id that must index a table of `size` (kNoId allowed when `noneAllowed`).
    void checkId(std::uint32_t id, std::size_t size, bool noneAllowed, const std::string& path,
                 const char* what, const char* table) const {
        if (id == kNoId && noneAllowed) return;
        if (id == kNoId || id >= size)
            fail(path, std::string(what) + " " +
                           (id == kNoId ? std::string("null") : std::to_string(id)) +
                           " is not in '" + table + "' (" + std::to_string(size) + " " + table +
                           ")");
    }
    void checkRange(std::int64_t v, std::int64_t lo, std::int64_t hi,
                    const std::string& path) const {
        if (v < lo || v > hi)
            fail(path, "must be from " + std::to_string(lo) + " to " + std::to_string(hi));
    }

  private:
    std::string file_;
    JsonLineMap lines_;
};

struct FieldReader {
    const Reader& r;
    const ordered_json& j;
    const std::string& path;
    template <typename T>
    void operator()(const char* key, Added<T> added) {
        if (j.contains(key)) (*this)(key, added.v);
    }
    template <typename T>
    void operator()(const char* key, T& v) {
        const ordered_json& x = r.at(j, path, key);
        const std::string p = JsonLineMap::child(path, key);
        if constexpr (std::is_same_v<T, RayKind>)
            v = r.enumValue<RayKind>(kRayKindNames, x, p);
        else if constexpr (std::is_same_v<T, LeafReason>)
            v = r.enumValue<LeafReason>(kLeafReasonNames, x, p);
        else if constexpr (std::is_same_v<T, ShadingTermKind>)
            v = r.enumValue<ShadingTermKind>(kShadingTermNames, x, p);
        else if constexpr (std::is_same_v<T, bool>) {
            if (!x.is_boolean()) r.fail(p, "expected true or false");
            v = x.get<bool>();
        } else if constexpr (std::is_same_v<T, double>)
            v = r.number(x, p);
        else if constexpr (std::is_same_v<T, std::uint32_t>)
            v = r.idValue(x, p);
        else if constexpr (std::is_integral_v<T>)
            v = static_cast<T>(
                r.integer(x, p, std::numeric_limits<T>::min(), std::numeric_limits<T>::max()));
        else {  // std::array
            if (!x.is_array() || x.size() != v.size())
                r.fail(p, "expected an array of " + std::to_string(v.size()));
            for (std::size_t i = 0; i < v.size(); ++i) {
                using X = std::decay_t<decltype(v[i])>;
                const std::string ep = JsonLineMap::element(p, i);
                if constexpr (std::is_same_v<X, double>)
                    v[i] = r.number(x[i], ep);
                else
                    v[i] = static_cast<X>(r.integer(x[i], ep, std::numeric_limits<X>::min(),
                                                    std::numeric_limits<X>::max()));
            }
        }
    }
};

ordered_json vec(const Vec3& v) {
    return {number(v.x), number(v.y), number(v.z)};
}

template <std::size_t I = 0>
Event readEvent(const Reader& r, const std::string& type, const ordered_json& j,
                const std::string& path) {
    if constexpr (I == std::variant_size_v<Event>) {
        std::string all;
        for (auto n : kEventNames) all += (all.empty() ? "" : ", ") + std::string(n);
        r.fail(JsonLineMap::child(path, "type"),
               "unknown event type '" + printable(type) + "' (" + all + ")");
    } else {
        if (type != kEventNames[I]) return readEvent<I + 1>(r, type, j, path);
        std::variant_alternative_t<I, Event> e{};
        // What an added field reads as when the file has none: "not recorded" (readTrace fills
        // in the leaf cost from the node's outcome and the frame from the file's "image").
        if constexpr (std::is_same_v<decltype(e), BuildNode>)
            e.cIsect = e.leafCost = std::numeric_limits<double>::quiet_NaN();
        fields(e, FieldReader{r, j, path});
        return e;
    }
}

}  // namespace

std::string traceToJson(const EventLog& log, const TraceInfo& info) {
    ordered_json root;
    root["format"] = "raystep-trace";
    root["version"] = kTraceFormatVersion;
    root["what"] = info.what;
    root["scene"] = info.scene;
    root["accel"] = info.accel;
    if (info.pixelX >= 0) root["pixel"] = {info.pixelX, info.pixelY};
    if (info.width > 0) root["image"] = {info.width, info.height};
    root["cap"] = log.cap();
    root["dropped"] = log.dropped();
    ordered_json rays = ordered_json::array();
    for (const RayRecord& r : log.rays())
        rays.push_back({{"kind", enumName(kRayKindNames, r.kind)},
                        {"depth", r.depth},
                        {"parent", id(r.parent)},
                        {"origin", vec(r.origin)},
                        {"dir", vec(r.dir)},
                        {"t_min", number(r.tMin)},
                        {"t_max", number(r.tMax)}});
    root["rays"] = std::move(rays);
    ordered_json nodes = ordered_json::array();
    for (const NodeRecord& n : log.nodes())
        nodes.push_back({{"lo", {number(n.lo[0]), number(n.lo[1]), number(n.lo[2])}},
                         {"hi", {number(n.hi[0]), number(n.hi[1]), number(n.hi[2])}}});
    root["nodes"] = std::move(nodes);
    // One value per line: diffable, and a reader's error names a useful line.
    std::string out = "{\n";
    bool first = true;
    for (auto it = root.begin(); it != root.end(); ++it) {
        out += first ? "" : ",\n";
        first = false;
        out += "  " + ordered_json(it.key()).dump() + ": ";
        if (it->is_array() && !it->empty()) {
            out += "[\n";
            for (std::size_t i = 0; i < it->size(); ++i)
                out += "    " + (*it)[i].dump() + (i + 1 < it->size() ? ",\n" : "\n");
            out += "  ]";
        } else {
            out += it->dump();
        }
    }
    // The events, by far the most, are written one at a time: a tree of millions of JSON values
    // would take several times the memory of the text.
    const auto& events = log.events();
    out += ",\n  \"events\": ";
    out += events.empty() ? "[]" : "[\n";
    for (std::size_t i = 0; i < events.size(); ++i) {
        ordered_json j;
        j["type"] = kEventNames[events[i].index()];
        std::visit(
            [&](const auto& e) {
                auto copy = e;
                fields(copy, Writer{j});
            },
            events[i]);
        out += "    " + j.dump() + (i + 1 < events.size() ? ",\n" : "\n  ]");
    }
    return out + "\n}\n";
}

namespace {

/// Every id and small field of an event in range: replays and the app index tables and arrays
/// with them. Node ids are checked when the file has a node table (a build's); a pixel's trace
/// names the nodes of a structure it does not hold.
void checkEvent(const Reader& r, const Event& e, const EventLog& log, std::size_t nodes,
                const std::string& p) {
    const auto child = [&](const char* key) { return JsonLineMap::child(p, key); };
    std::visit(
        [&](const auto& ev) {
            using E = std::decay_t<decltype(ev)>;
            if constexpr (requires { ev.ray; })
                r.checkId(ev.ray, log.rays().size(), true, child("ray"), "ray", "rays");
            if constexpr (std::is_same_v<E, RayBegin>)
                r.checkId(ev.parent, log.rays().size(), true, child("parent"), "ray", "rays");
            constexpr bool build = std::is_same_v<E, BuildNode> ||
                                   std::is_same_v<E, SplitCandidate> ||
                                   std::is_same_v<E, SplitChosen> || std::is_same_v<E, LeafMade>;
            if constexpr (requires { ev.node; })
                if (build || nodes > 0)
                    r.checkId(ev.node, nodes, false, child("node"), "node", "nodes");
            if constexpr (std::is_same_v<E, BuildNode>)
                r.checkId(ev.parent, nodes, true, child("parent"), "node", "nodes");
            if constexpr (requires { ev.axis; }) r.checkRange(ev.axis, 0, 2, child("axis"));
            if constexpr (std::is_same_v<E, DdaCell>) r.checkRange(ev.axes, 0, 7, child("axes"));
            if constexpr (std::is_same_v<E, PixelResult>) {
                // A frame of 0 by 0 is a trace that did not record it.
                r.checkRange(ev.width, 0, 1 << 20, child("width"));
                r.checkRange(ev.height, 0, 1 << 20, child("height"));
                if (ev.width > 0 && ev.height > 0) {
                    r.checkRange(ev.x, 0, ev.width - 1, child("x"));
                    r.checkRange(ev.y, 0, ev.height - 1, child("y"));
                }
            }
            if constexpr (std::is_same_v<E, DdaSetup>) {
                r.checkRange(ev.dims, 2, 3, child("dims"));
                for (std::size_t k = 0; k < ev.step.size(); ++k)
                    r.checkRange(ev.step[k], -1, 1, JsonLineMap::element(child("step"), k));
            }
        },
        e);
}

/// What a trace written before a field was added says in its place (docs/trace-format.md):
/// a blocked shadow ray was a hit on no primitive at infinity, a build node's leaf cost is its
/// outcome's, and a pixel's frame is the file's "image".
void fillAdded(std::vector<Event>& events, const TraceInfo& info) {
    std::map<std::uint32_t, std::size_t> open;  // node -> its BuildNode without a leaf cost
    double cIsect = std::numeric_limits<double>::quiet_NaN();  // the build's, once known
    for (std::size_t i = 0; i < events.size(); ++i) {
        Event& e = events[i];
        if (const auto* h = std::get_if<RayHit>(&e); h && h->prim == kNoId && std::isinf(h->t)) {
            e = blockedBy(events, h->ray, 0, i);  // back to the ray's own start
        } else if (auto* b = std::get_if<BuildNode>(&e)) {
            // A node opened again (a hand-made trace) is the one its outcome belongs to, with a
            // leaf cost or not: so reading a trace this wrote changes nothing.
            if (std::isnan(b->leafCost))
                open[b->node] = i;
            else
                open.erase(b->node);
        } else if (auto* p = std::get_if<PixelResult>(&e);
                   p && p->width == 0 && p->x < std::uint32_t(std::max(info.width, 0)) &&
                   p->y < std::uint32_t(std::max(info.height, 0))) {
            // The file's image, when the pixel is in it (a frame it is not in would not read).
            p->width = static_cast<std::uint32_t>(info.width);
            p->height = static_cast<std::uint32_t>(info.height);
        }
        std::optional<std::pair<std::uint32_t, double>> outcome;  // node, leaf cost
        if (const auto* c = std::get_if<SplitChosen>(&e)) outcome = {c->node, c->leafCost};
        if (const auto* l = std::get_if<LeafMade>(&e)) outcome = {l->node, l->leafCost};
        if (!outcome) continue;
        const auto at = open.find(outcome->first);
        if (at == open.end()) continue;
        auto& b = std::get<BuildNode>(events[at->second]);
        b.leafCost = outcome->second;
        if (b.prims > 0 && std::isnan(b.cIsect)) b.cIsect = b.leafCost / b.prims;
        if (!std::isnan(b.cIsect)) cIsect = b.cIsect;
        open.erase(at);
    }
    // An empty node's leaf cost says nothing of C_isect: the build's, from its other nodes.
    for (Event& e : events)
        if (auto* b = std::get_if<BuildNode>(&e); b && std::isnan(b->cIsect)) b->cIsect = cIsect;
}

EventLog readTrace(std::string_view text, const std::string& fileName, TraceInfo* info) {
    auto parsed = detail::parseJsonFile<TraceError, ordered_json>(text, fileName,
                                                                  /*comments=*/false);
    const ordered_json& root = parsed.root;
    const Reader r(fileName, std::move(parsed.lines));
    if (!root.is_object()) r.fail("", "a trace file holds one JSON object");
    const ordered_json& format = r.at(root, "", "format");
    if (format != "raystep-trace") r.fail("format", "expected \"raystep-trace\"");
    const auto version = r.integer(r.at(root, "", "version"), "version", 1, 1000000);
    if (version != kTraceFormatVersion)
        r.fail("version", "this raystep reads trace version " +
                              std::to_string(kTraceFormatVersion) + ", the file is version " +
                              std::to_string(version));
    constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
    std::size_t cap = std::numeric_limits<std::size_t>::max();
    if (root.contains("cap"))
        cap = static_cast<std::size_t>(r.integer(root["cap"], "cap", 0, kMax));
    EventLog log(cap);
    TraceInfo read;
    for (const auto& [key, field] :
         {std::pair{"scene", &read.scene}, {"accel", &read.accel}, {"what", &read.what}})
        if (root.contains(key)) *field = r.string(root[key], key);
    // [A, B], two whole numbers from lo to 2^20.
    const auto pair = [&](const char* key, const char* form, std::int64_t lo, int& a, int& b) {
        if (!root.contains(key)) return;
        const ordered_json& v = root[key];
        if (!v.is_array() || v.size() != 2) r.fail(key, std::string("expected ") + form);
        a = static_cast<int>(r.integer(v[0], JsonLineMap::element(key, 0), lo, 1 << 20));
        b = static_cast<int>(r.integer(v[1], JsonLineMap::element(key, 1), lo, 1 << 20));
    };
    pair("pixel", "[X, Y]", 0, read.pixelX, read.pixelY);
    pair("image", "[W, H]", 1, read.width, read.height);
    if (root.contains("dropped"))
        log.setDropped(static_cast<std::size_t>(r.integer(root["dropped"], "dropped", 0, kMax)));

    const auto vec3 = [&](const ordered_json& j, const std::string& p) {
        if (!j.is_array() || j.size() != 3) r.fail(p, "expected [x, y, z]");
        return Vec3(r.number(j[0], JsonLineMap::element(p, 0)),
                    r.number(j[1], JsonLineMap::element(p, 1)),
                    r.number(j[2], JsonLineMap::element(p, 2)));
    };
    const ordered_json& rays = r.at(root, "", "rays");
    if (!rays.is_array()) r.fail("rays", "expected an array");
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const std::string p = JsonLineMap::element("rays", i);
        const ordered_json& j = rays[i];
        r.requireObject(j, p);
        RayRecord rec{};
        rec.kind =
            r.enumValue<RayKind>(kRayKindNames, r.at(j, p, "kind"), JsonLineMap::child(p, "kind"));
        rec.depth = static_cast<std::uint8_t>(
            r.integer(r.at(j, p, "depth"), JsonLineMap::child(p, "depth"), 0, 255));
        rec.parent = r.idValue(r.at(j, p, "parent"), JsonLineMap::child(p, "parent"));
        r.checkId(rec.parent, rays.size(), true, JsonLineMap::child(p, "parent"), "ray", "rays");
        rec.origin = vec3(r.at(j, p, "origin"), JsonLineMap::child(p, "origin"));
        rec.dir = vec3(r.at(j, p, "dir"), JsonLineMap::child(p, "dir"));
        rec.tMin = r.number(r.at(j, p, "t_min"), JsonLineMap::child(p, "t_min"));
        rec.tMax = r.number(r.at(j, p, "t_max"), JsonLineMap::child(p, "t_max"));
        if (!isFinite(rec.origin) || !isFinite(rec.dir))
            r.fail(p, "a ray's origin and direction must be finite");
        log.addRay(rec);
    }
    std::size_t nodeCount = 0;
    if (root.contains("nodes")) {
        const ordered_json& nodes = root["nodes"];
        if (!nodes.is_array()) r.fail("nodes", "expected an array");
        nodeCount = nodes.size();
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            const std::string p = JsonLineMap::element("nodes", i);
            const Vec3 lo = vec3(r.at(nodes[i], p, "lo"), JsonLineMap::child(p, "lo"));
            const Vec3 hi = vec3(r.at(nodes[i], p, "hi"), JsonLineMap::child(p, "hi"));
            log.node(static_cast<std::uint32_t>(i), {lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z});
        }
    }
    const ordered_json& events = r.at(root, "", "events");
    if (!events.is_array()) r.fail("events", "expected an array");
    std::vector<Event> recorded;
    recorded.reserve(events.size());
    for (std::size_t i = 0; i < events.size(); ++i) {
        const std::string p = JsonLineMap::element("events", i);
        const ordered_json& j = events[i];
        const ordered_json& type = r.at(j, p, "type");
        if (!type.is_string()) r.fail(JsonLineMap::child(p, "type"), "expected a string");
        Event e = readEvent(r, type.get<std::string>(), j, p);
        // Ids must point into the tables, so a replay never reads past them.
        checkEvent(r, e, log, nodeCount, p);
        recorded.push_back(e);
    }
    fillAdded(recorded, read);
    for (const Event& e : recorded)
        log.append(e);  // past the cap too: the file is what was recorded
    if (info) *info = read;
    return log;
}

}  // namespace

EventLog traceFromJson(std::string_view text, const std::string& fileName, TraceInfo* info) {
    return detail::guarded<TraceError>(fileName, [&] { return readTrace(text, fileName, info); });
}

}  // namespace raystep

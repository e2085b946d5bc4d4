// The tables of structures and of their options, and what is read from them.
#include "raystep/accel/structure_info.h"

#include "raystep/accel/grid.h"
#include "raystep/accel/kdtree_build.h"
#include "raystep/base/format.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace raystep {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
using O = AccelOption;
using T = OptionType;

// In AccelOption's order. The limits are what the CLI, the lesson reader and the live controls
// accept; a default is AccelOptions{}'s (a test compares them).
constexpr std::array<OptionInfo, 12> kOptions{{
    {.option = O::Split,
     .key = "split",
     .type = T::Choice,
     .defaultValue = double(int(SplitMethod::Sah)),
     .doc = "kd-tree / BVH split: midpoint, median or sah"},
    {.option = O::Mailbox,
     .key = "mailbox",
     .type = T::Switch,
     .hi = 1,
     .defaultValue = 1,
     .doc = "Grid and kd-tree: test each primitive once per ray (on, off)"},
    {.option = O::GridRes,
     .key = "grid_res",
     .type = T::Cells,
     .lo = 1,
     .hi = GridOptions::kMaxCellsPerAxis,
     .autoZero = true,
     .doc = "Grid: cells per axis NX,NY,NZ instead of the rule"},
    {.option = O::GridLambda,
     .key = "grid_lambda",
     .type = T::Number,
     .hi = kInf,  // past the caps a larger lambda changes nothing, and is no error
     .loOpen = true,
     .defaultValue = 4,
     .controlHi = 1000,
     .doc = "Grid: cells per primitive, lambda N cells in all (Cleary-Wyvill rule)"},
    {.option = O::LeafSize,
     .key = "leaf_size",
     .type = T::Whole,
     .lo = 1,
     .hi = 1'000'000,
     .autoZero = true,
     .doc = "Trees: this many primitives or fewer make a leaf (kd: SAH 1, else 4; BVH 4)"},
    {.option = O::MaxDepth,
     .key = "max_depth",
     .type = T::Whole,
     .lo = 1,
     .hi = kdbuild::kMaxDepthCap,
     .autoZero = true,
     .doc = "kd-tree: depth limit (default round(8 + 1.3 log2 N))"},
    {.option = O::CTrav,
     .key = "c_trav",
     .type = T::Number,
     .hi = kInf,
     .defaultValue = 1,
     .sahOnly = true,
     .controlHi = 1000,
     .doc = "Tree SAH: cost of a traversal step (default 1)"},
    {.option = O::CIsect,
     .key = "c_isect",
     .type = T::Number,
     .hi = kInf,
     .loOpen = true,
     .defaultValue = 5,
     .sahOnly = true,
     .controlHi = 1000,
     .doc = "Tree SAH: cost of a primitive test (default 5)"},
    {.option = O::EmptyBonus,
     .key = "empty_bonus",
     .type = T::Number,
     .hi = 1,
     .defaultValue = 0.5,
     .sahOnly = true,
     .doc = "kd-tree SAH: discount for a split with an empty side, 0..1 (default 0.5)"},
    {.option = O::Buckets,
     .key = "buckets",
     .type = T::Whole,
     .lo = 2,
     .hi = 256,
     .defaultValue = 12,
     .sahOnly = true,
     .doc = "BVH SAH: bins along the axis (default 12)"},
    {.option = O::BinAbove,
     .key = "bin_above",
     .type = T::Whole,
     .lo = 1,
     .hi = INT_MAX,
     .autoZero = true,
     .sahOnly = true,
     .doc = "kd-tree SAH: nodes of more primitives pick among 256 bins per axis (default: the "
            "exact event sweep everywhere)"},
    {.option = O::KdBuild,
     .key = "kd_build",
     .type = T::Choice,
     .sahOnly = true,
     .doc = "kd-tree SAH build: exact (every split event, perfect splits) or fast (16-32 bins "
            "per axis, all cores)"},
}};

constexpr std::array<SplitMethod, 3> kAllSplits{SplitMethod::Midpoint, SplitMethod::Median,
                                                SplitMethod::Sah};
constexpr std::array<AccelOption, 0> kNoOptions{};
constexpr std::array<AccelOption, 3> kGridOptions{O::GridRes, O::GridLambda, O::Mailbox};
constexpr std::array<AccelOption, 9> kKdTreeOptions{O::Split,   O::LeafSize, O::MaxDepth,
                                                    O::CTrav,   O::CIsect,   O::EmptyBonus,
                                                    O::Mailbox, O::BinAbove, O::KdBuild};
constexpr std::array<AccelOption, 5> kBvhOptions{O::Split, O::LeafSize, O::CTrav, O::CIsect,
                                                 O::Buckets};

// In AccelKind's order.
constexpr std::array<StructureInfo, kAccelKindCount> kStructures{{
    {.kind = AccelKind::BruteForce,
     .name = "bruteforce",
     .label = [](Language l) { return tr(l, "brute force"); },
     .subdivides = Subdivides::Nothing,
     .splits = {},
     .recordsBuild = false,
     .options = kNoOptions},
    {.kind = AccelKind::Grid,
     .name = "grid",
     .label = [](Language l) { return tr(l, "grid"); },
     .subdivides = Subdivides::Space,
     .splits = {},
     .recordsBuild = false,
     .options = kGridOptions},
    {.kind = AccelKind::KdTree,
     .name = "kdtree",
     .label = [](Language l) { return tr(l, "kd-tree"); },
     .subdivides = Subdivides::Space,
     .splits = kAllSplits,
     .recordsBuild = true,
     .options = kKdTreeOptions},
    {.kind = AccelKind::Bvh,
     .name = "bvh",
     .label = [](Language l) { return tr(l, "BVH"); },
     .subdivides = Subdivides::Primitives,
     .splits = kAllSplits,
     .recordsBuild = true,
     .options = kBvhOptions},
}};

constexpr bool inOrder() {
    for (std::size_t i = 0; i < kStructures.size(); ++i)
        if (static_cast<std::size_t>(kStructures[i].kind) != i) return false;
    for (std::size_t i = 0; i < kOptions.size(); ++i)
        if (static_cast<std::size_t>(kOptions[i].option) != i) return false;
    return true;
}
static_assert(inOrder(), "a row of kStructures or kOptions out of its enum's order");

/// A limit as text: whole limits in full ("1000000", not %g's "1e+06").
std::string number(double v) {
    if (v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
    return formatNumber(v);
}

}  // namespace

std::span<const StructureInfo> structures() {
    return kStructures;
}
const StructureInfo& structureInfo(AccelKind kind) {
    const auto i = static_cast<std::size_t>(kind);
    if (i >= kStructures.size()) throw std::logic_error("unknown accelerator kind");
    return kStructures[i];
}
std::span<const OptionInfo> accelOptions() {
    return kOptions;
}
const OptionInfo& optionInfo(AccelOption option) {
    const auto i = static_cast<std::size_t>(option);
    if (i >= kOptions.size()) throw std::logic_error("unknown accelerator option");
    return kOptions[i];
}

std::optional<AccelKind> parseAccelKind(std::string_view name) {
    for (const StructureInfo& s : kStructures)
        if (s.name == name) return s.kind;
    return std::nullopt;
}
std::string_view accelKindName(AccelKind kind) {
    return structureInfo(kind).name;
}
std::string structureLabel(AccelKind kind, Language lang) {
    return structureInfo(kind).label(lang);
}

bool readsOption(AccelKind kind, AccelOption option) {
    for (const AccelOption o : structureInfo(kind).options)
        if (o == option) return true;
    return false;
}
bool readsOption(AccelKind kind, AccelOption option, SplitMethod split) {
    return readsOption(kind, option) && (!optionInfo(option).sahOnly || split == SplitMethod::Sah);
}

std::string kindList(bool (*keep)(AccelKind)) {
    std::vector<std::string_view> names;
    for (const StructureInfo& s : kStructures)
        if (!keep || keep(s.kind)) names.push_back(s.name);
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i) out += i + 1 == names.size() ? " or " : ", ";
        out += names[i];
    }
    return out;
}

std::string choiceName(const StructureChoice& c) {
    std::string s(accelKindName(c.kind));
    if (c.split) s += " " + std::string(name(*c.split));
    return s;
}

namespace {
/// The words of a comma list, spaces around them dropped; an empty word stays (it is refused).
std::vector<std::string_view> words(std::string_view text) {
    std::vector<std::string_view> out;
    for (std::size_t start = 0;;) {
        const std::size_t comma = text.find(',', start);
        std::string_view w = text.substr(start, comma == text.npos ? text.npos : comma - start);
        while (!w.empty() && w.front() == ' ') w.remove_prefix(1);
        while (!w.empty() && w.back() == ' ') w.remove_suffix(1);
        out.push_back(w);
        if (comma == text.npos) return out;
        start = comma + 1;
    }
}
}  // namespace

std::variant<std::vector<StructureChoice>, std::string> parseStructureChoices(
    std::string_view kindText, std::optional<std::string_view> splitText, std::string_view accelKey,
    std::string_view splitKey) {
    const auto problem = [](std::string_view key, std::string_view text, std::string_view why) {
        return std::string(key) + " " + std::string(text) + ": " + std::string(why);
    };
    std::vector<AccelKind> kinds;
    for (const std::string_view w : words(kindText)) {
        const auto kind = parseAccelKind(w);
        if (!kind)
            return problem(accelKey, kindText,
                           "expected a comma list of " + kindList() + " (" +
                               (w.empty() ? std::string("an empty name") : std::string(w)) + ")");
        if (std::find(kinds.begin(), kinds.end(), *kind) != kinds.end())
            return problem(accelKey, kindText, std::string(w) + " twice");
        kinds.push_back(*kind);
    }
    std::vector<SplitMethod> splits;
    if (splitText) {
        for (const std::string_view w : words(*splitText)) {
            const auto split = parseSplitMethod(w);
            if (!split)
                return problem(splitKey, *splitText,
                               "expected a comma list of midpoint, median or sah (" +
                                   (w.empty() ? std::string("an empty name") : std::string(w)) +
                                   ")");
            if (std::find(splits.begin(), splits.end(), *split) == splits.end())
                splits.push_back(*split);
        }
    } else if (kinds.size() == 1 && hasSplit(kinds[0])) {
        const auto all = structureInfo(kinds[0]).splits;
        splits.assign(all.begin(), all.end());
    } else {
        splits = {SplitMethod::Sah};
    }
    std::vector<StructureChoice> out;
    for (const AccelKind kind : kinds) {
        if (!hasSplit(kind)) {
            out.push_back({kind, std::nullopt});
            continue;
        }
        for (const SplitMethod split : splits) out.push_back({kind, split});
    }
    return out;
}

std::string cliFlag(AccelOption option) {
    std::string flag = "--" + std::string(optionInfo(option).key);
    for (char& c : flag)
        if (c == '_') c = '-';
    return flag;
}

std::optional<std::string> optionProblem(AccelOption option, double value) {
    const OptionInfo& o = optionInfo(option);
    if (o.type == OptionType::Switch || o.type == OptionType::Choice) return std::nullopt;
    if (!std::isfinite(value)) return "must be a finite number";
    const bool whole = o.type == OptionType::Whole || o.type == OptionType::Cells;
    if (whole && value != std::floor(value)) return "expected a whole number";
    const bool below = o.loOpen ? !(value > o.lo) : value < o.lo;
    if (!below && value <= o.hi) return std::nullopt;
    if (std::isinf(o.hi))
        return o.loOpen ? "must be greater than " + number(o.lo)
                        : "must be " + number(o.lo) + " or more";
    return "must be from " + number(o.lo) + " to " + number(o.hi);
}

std::pair<double, double> controlRange(AccelOption option, double step) {
    const OptionInfo& o = optionInfo(option);
    double lo = o.loOpen ? o.lo + step : o.lo;
    if (o.autoZero) lo = 0.0;
    return {lo, std::isinf(o.hi) ? o.controlHi : o.hi};
}

}  // namespace raystep

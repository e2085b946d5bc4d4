#pragma once
// One row per structure: what the CLI, the lessons and the app ask of a kind (its name, the
// split methods it offers, whether its build can be replayed, the options it reads with their
// limits and defaults). Every client reads these tables instead of keeping its own list, so a new
// structure is its row here, its files and its outline (outline.h), nothing in app/.
#include "raystep/accel/sah.h"
#include "raystep/base/i18n.h"

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace raystep {

/// The closed set of structures; AcceleratorT (accel.h) holds one alternative per kind, in order.
enum class AccelKind { BruteForce, Grid, KdTree, Bvh };
/// How many kinds: the variant (accel.h) and the table (structure_info.cpp) both assert it.
inline constexpr std::size_t kAccelKindCount = 4;

/// What a structure subdivides: the slides' two families, and brute force, which does neither.
enum class Subdivides { Nothing, Space, Primitives };

/// A build parameter a structure may read (AccelOptions holds the values).
enum class AccelOption {
    Split,       // the split method (choices: the structure's `splits`)
    Mailbox,     // test a primitive listed in several cells or leaves once per ray
    GridRes,     // cells per axis (each within the limits; kMaxCells in all)
    GridLambda,  // Cleary-Wyvill: cells per primitive
    LeafSize,    // this many primitives or fewer make a leaf
    MaxDepth,    // the kd-tree's depth limit
    CTrav,       // SAH: cost of a traversal step
    CIsect,      // SAH: cost of a ray-primitive test
    EmptyBonus,  // kd-tree SAH: discount for a split with an empty side
    Buckets,     // BVH SAH: bins along the axis
    BinAbove,    // kd-tree SAH: nodes of more primitives choose among bins
    KdBuild,     // kd-tree SAH: exact or fast build (choices: exact, fast)
};

/// How an option's value is written.
enum class OptionType { Number, Whole, Switch, Choice, Cells };

/// One option: its spelling, its limits (the ones every reader checks) and its default.
struct OptionInfo {
    AccelOption option;
    std::string_view key;  // a lesson's setup key; the CLI spells it --key with '-' for '_'
    OptionType type;
    double lo = 0.0, hi = 0.0;  // accepted values (Cells: per axis); hi may be infinite
    bool loOpen = false;        // lo itself refused (a cost of 0 per test)
    double defaultValue = 0.0;  // AccelOptions{}'s; for `autoZero`, 0 is the rule's value
    bool autoZero = false;      // 0 (below lo) means "the structure's rule" (shown as auto)
    bool sahOnly = false;       // read only when the split method is the SAH
    double controlHi = 0.0;     // a control's top where `hi` is infinite (a spin box needs one)
    std::string_view doc;       // one line, English (the CLI's help)
};

/// One structure.
struct StructureInfo {
    AccelKind kind;
    std::string_view name;           // "kdtree": the CLI's and lessons' spelling, trace files, JSON
    std::string (*label)(Language);  // "kd-tree", in a language (the catalogue's)
    Subdivides subdivides;
    std::span<const SplitMethod> splits;   // empty: no split choice (grid, brute force)
    bool recordsBuild;                     // its construction is recorded and replayed
    std::span<const AccelOption> options;  // the options its build reads
};

/// Every structure, in AccelKind's order.
std::span<const StructureInfo> structures();
const StructureInfo& structureInfo(AccelKind kind);
/// Every option, in AccelOption's order.
std::span<const OptionInfo> accelOptions();
const OptionInfo& optionInfo(AccelOption option);

/// Parses a structure's name ("bruteforce|grid|kdtree|bvh"); nullopt for anything else.
std::optional<AccelKind> parseAccelKind(std::string_view name);
std::string_view accelKindName(AccelKind kind);
/// The structure's name for people ("kd-tree"), in `lang`.
std::string structureLabel(AccelKind kind, Language lang = Language::En);

inline bool hasSplit(AccelKind kind) {
    return !structureInfo(kind).splits.empty();
}
inline bool recordsBuild(AccelKind kind) {
    return structureInfo(kind).recordsBuild;
}
/// Brute force's "every ray against every primitive": it subdivides nothing.
inline bool testsEveryPrimitive(AccelKind kind) {
    return structureInfo(kind).subdivides == Subdivides::Nothing;
}
/// Whether `kind`'s build reads `option` (whatever the split method).
bool readsOption(AccelKind kind, AccelOption option);
/// The same for the split method in use: the SAH's costs are read by the SAH only.
bool readsOption(AccelKind kind, AccelOption option, SplitMethod split);

/// The names of the structures that pass `keep` (all by default), for messages:
/// "bruteforce, grid, kdtree or bvh".
std::string kindList(bool (*keep)(AccelKind) = nullptr);
/// One structure to build: a kind and, for a tree, its split method (a grid has none).
struct StructureChoice {
    AccelKind kind = AccelKind::Grid;
    std::optional<SplitMethod> split;
    bool operator==(const StructureChoice&) const = default;
};
/// "grid", "kdtree SAH": the choice as render --stats and the compare rows name it.
std::string choiceName(const StructureChoice& c);
/// The structures a comma list of kinds ("grid,kdtree,bvh") and of split methods ("sah" or
/// "midpoint,median") ask for, in the list's order: each tree once per split method; a single
/// tree without `splits` gives its split methods against each other (the slides' comparison),
/// several kinds without `splits` take the SAH. The problem in one line (naming `accelKey` or
/// `splitKey`, the value and the word refused) when a name is unknown, a kind given twice or a
/// list empty.
std::variant<std::vector<StructureChoice>, std::string> parseStructureChoices(
    std::string_view kinds, std::optional<std::string_view> splits,
    std::string_view accelKey = "--accel", std::string_view splitKey = "--split");

/// The CLI's spelling of an option: "--c-isect".
std::string cliFlag(AccelOption option);
/// Why `value` is refused for `option` ("must be from 1 to 60"), or nullopt when it is accepted.
/// A Cells option checks one axis; a Switch or Choice is not a number and is always accepted.
std::optional<std::string> optionProblem(AccelOption option, double value);
/// The limits as a control shows them: [lo, hi], with an open lo moved up by `step` and an
/// infinite hi replaced by controlHi; 0 first when the option has an auto value.
std::pair<double, double> controlRange(AccelOption option, double step = 0.01);

}  // namespace raystep

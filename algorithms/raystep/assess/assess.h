#pragma once
// A student's run checked against raystep's own (docs/assignment-format.md): for each ray, passed
// or the first record that differs, what raystep's recorded run has there, the lecture's
// quantity that decides it, and the classic mistake (mistakes.h) the run matches, if one does.
#include "raystep/accel/accel.h"
#include "raystep/assess/mistakes.h"
#include "raystep/assess/student_trace.h"
#include "raystep/base/i18n.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace raystep {

/// One step of the reference run: a cell, a node, or (kind None) the tests made before any.
struct ReferenceUnit {
    enum class Kind : std::uint8_t { None, Cell, Node };
    Kind kind = Kind::None;
    std::array<long long, 3> cell{};
    std::array<double, 3> tMax{};  // the cell's tMax (inf: parallel)
    unsigned axes = 0;             // axes stepped into this cell (0 for the first)
    std::uint32_t node = kNoId;
    double tNear = 0.0, tFar = 0.0;      // a node's interval; a cell's entry and exit
    std::vector<std::uint32_t> tests;    // primitives tested here, in order
    std::vector<std::uint32_t> skipped;  // mailbox skips here
    std::vector<std::pair<std::uint32_t, double>> hits;  // tests that found a nearer hit
};

/// What raystep's own run did on one ray.
struct ReferenceRay {
    int dims = 2;
    bool cells = true;  // the walk is a grid's (cells) or a tree's (nodes)
    std::array<int, 3> step{};
    std::array<double, 3> tDelta{};
    bool entersGrid = false;
    double tEnter = 0.0, tGridExit = 0.0;
    std::vector<ReferenceUnit> units;
    std::vector<NodeSkip> skips;  // trees: the nodes not entered
    bool hit = false;
    std::uint32_t prim = kNoId;
    double t = kInfinity;
    int walkCount() const;  // cells or nodes
};

/// The node of a tree, for explaining a traversal: its parent, children and split.
struct ReferenceNode {
    std::uint32_t parent = kNoId;
    std::array<std::uint32_t, 2> children{kNoId, kNoId};
    int axis = -1;
    std::optional<double> split;  // the kd-tree's plane
    bool leaf = false;
};

/// What a student's rays are checked against: a bare DDA walk on a grid, or a scene's structure
/// (which must outlive the Reference).
class Reference {
  public:
    /// The exact walk of dda.h on `grid` (dims 2: the first two axes).
    static Reference dda(const GridSpec<3, double>& grid, int dims);
    /// A built structure over a scene of either kind (AnyStructure holds one).
    static Reference structure(const AnyStructure& structure, AccelKind kind);

    int dims() const { return dims_; }
    AccelKind kind() const { return kind_; }
    /// The grid walked (bare walk, grid structure): the DDA variants run on it.
    const std::optional<GridSpec<3, double>>& grid() const { return grid_; }
    const std::vector<ReferenceNode>& nodes() const { return nodes_; }
    bool bare() const { return !structure_; }
    /// Raystep's own run of the student's ray.
    ReferenceRay run(const StudentRay& ray) const;
    /// The same run's events (a structure's), for a view to replay.
    EventLog record(const StudentRay& ray) const;

  private:
    int dims_ = 2;
    AccelKind kind_ = AccelKind::Grid;
    std::optional<GridSpec<3, double>> grid_;
    std::vector<ReferenceNode> nodes_;
    const AnyStructure* structure_ = nullptr;
};

/// Where a student's ray first differs from the reference.
struct Divergence {
    int index = 0;         // 0-based among the ray's walk records (cells or nodes); -1 before any
    int line = 0;          // the record's line in the file (the ray's own line if none)
    std::string record;    // "cell", "tMax", "node", "test", "hit", "miss", "end"
    std::string expected;  // JSON text of what the reference has there ("null": nothing)
    std::string got;       // JSON text of the student's record ("null": nothing)
    std::string quantity;  // the lecture's quantity that decides it: "tMaxY", "stepX", "tFar"
    std::string explanation;
};

struct RayVerdict {
    int ray = 0;
    int line = 0;
    bool passed = false;
    int walkRecords = 0;  // the student's cells or nodes
    std::optional<Divergence> divergence;
    std::optional<Mistake> mistake;
    ReferenceRay reference;
};

struct Assessment {
    std::string file;
    std::vector<RayVerdict> rays;
    int passed() const;
    double score() const;  // passed / rays
    bool allPassed() const { return passed() == int(rays.size()); }
};

/// Checks every ray of `trace` against `reference`; the explanations are in `lang`.
Assessment assess(const StudentTrace& trace, const Reference& reference, Language lang);

/// Where a divergence is, in words: "cell record 4", "the end of the walk".
std::string divergencePlace(const Divergence& d, Language lang);

/// The verdict as docs/assignment-format.md's JSON (`--json`).
std::string assessmentJson(const Assessment& a, Language lang);
/// The verdict as text: a line per ray, the divergence explained, the score.
std::string assessmentText(const Assessment& a, Language lang);

}  // namespace raystep

#pragma once
// Replay: what a recorded log shows after its first `cursor` events. A view is a pure function of
// (scene, log, cursor); this is the "log, cursor" part, shared by the app, the course's checks
// and the tests. Seeking backwards is as cheap as forwards: the replay keeps a checkpoint every
// few thousand events and folds forward from the nearest one.
#include "raystep/trace/events.h"

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace raystep {

/// The algorithm's variables at a cursor, as the inspector and the views show them.
struct ReplayState {
    std::size_t cursor = 0;  // events [0, cursor) are applied

    // The ray being traced: the last ray an event named.
    std::uint32_t ray = kNoId;
    // Its DDA (grid): set-up, the current cell with tMax, and the cells visited so far.
    std::optional<DdaSetup> ddaSetup;
    std::optional<DdaCell> ddaCell;
    std::vector<std::array<std::int32_t, 3>> visitedCells;
    // Its primitive tests and mailbox skips, in order, and the nearest hit so far.
    std::vector<PrimitiveTest> tests;
    std::vector<std::uint32_t> mailboxSkips;
    std::optional<double> nearestT;
    std::uint32_t nearestPrim = kNoId;
    // Its tree traversal: nodes entered and skipped, the current node and its interval.
    std::vector<std::uint32_t> nodesEntered;
    std::vector<std::uint32_t> nodesSkipped;
    std::optional<NodeEnter> node;
    // How it ended (once it has): its nearest hit, blocked (a shadow ray), or no hit.
    std::optional<RayHit> hit;
    std::optional<RayBlocked> blocked;
    bool missed = false;

    // A build: the node being split, its candidates so far, its choice, and the leaves made.
    std::optional<BuildNode> buildNode;
    std::vector<SplitCandidate> candidates;
    std::optional<SplitChosen> chosen;
    std::size_t nodesBuilt = 0;
    std::size_t leavesMade = 0;
    std::optional<LeafMade> lastLeaf;

    // Shading and the pixel.
    std::vector<ShadingTerm> terms;  // of the current ray
    std::optional<PixelResult> pixel;
};

/// Applies one event to a state (the fold's step).
void applyEvent(ReplayState& state, const Event& event);

/// A cursor over a log (which must outlive it).
class Replay {
  public:
    static constexpr std::size_t kCheckpointEvery = 4096;
    /// Bytes all checkpoints may hold together: a ray's state grows with its tests (brute force
    /// on a million triangles records millions), so a copy every few thousand events grew as
    /// the square of the log (9.5 GB for 2.4 million events). Past it they are spaced wider.
    static constexpr std::size_t kCheckpointBytes = std::size_t(64) << 20;

    explicit Replay(const EventLog& log);

    /// The state after the first `cursor` events (clamped to the log's size).
    const ReplayState& seek(std::size_t cursor);
    const ReplayState& state() const { return state_; }
    std::size_t size() const { return log_->events().size(); }

    /// The first event at or after `from` whose variant index is `kind` (e.g.
    /// `variantIndex<DdaCell>()`), or size() if there is none. Backwards: the last before `from`.
    std::size_t nextOfKind(std::size_t from, std::size_t kind) const;
    std::size_t previousOfKind(std::size_t from, std::size_t kind) const;

  private:
    const EventLog* log_;
    std::vector<ReplayState> checkpoints_;  // checkpoints_[i]: the state at i * every_
    std::size_t every_ = kCheckpointEvery;  // a power of two times kCheckpointEvery
    ReplayState state_;
};

/// The variant index of an event type, for nextOfKind.
template <typename E, std::size_t I = 0>
constexpr std::size_t variantIndex() {
    if constexpr (std::is_same_v<std::variant_alternative_t<I, Event>, E>)
        return I;
    else
        return variantIndex<E, I + 1>();
}

}  // namespace raystep

#include "raystep/trace/replay.h"

#include <algorithm>

namespace raystep {

namespace {
/// A new ray starts: forget the previous ray's traversal.
void startRay(ReplayState& s, std::uint32_t ray) {
    s.ray = ray;
    s.ddaSetup.reset();
    s.ddaCell.reset();
    s.visitedCells.clear();
    s.tests.clear();
    s.mailboxSkips.clear();
    s.nearestT.reset();
    s.nearestPrim = kNoId;
    s.nodesEntered.clear();
    s.nodesSkipped.clear();
    s.node.reset();
    s.hit.reset();
    s.blocked.reset();
    s.missed = false;
}
}  // namespace

void applyEvent(ReplayState& s, const Event& event) {
    ++s.cursor;
    std::visit(
        [&](const auto& e) {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, RayBegin>) {
                startRay(s, e.ray);
            } else if constexpr (std::is_same_v<E, DdaSetup>) {
                s.ddaSetup = e;
            } else if constexpr (std::is_same_v<E, DdaCell>) {
                s.ddaCell = e;
                s.visitedCells.push_back(e.cell);
            } else if constexpr (std::is_same_v<E, MailboxSkip>) {
                s.mailboxSkips.push_back(e.prim);
            } else if constexpr (std::is_same_v<E, PrimitiveTest>) {
                s.tests.push_back(e);
                // A hit counts as the nearest so far only if it is nearer (or a lower id at the
                // same t): the structures' rule, so the replay agrees with the ray's hit.
                if (e.hit && (!s.nearestT || e.t < *s.nearestT ||
                              (e.t == *s.nearestT && e.prim < s.nearestPrim))) {
                    s.nearestT = e.t;
                    s.nearestPrim = e.prim;
                }
            } else if constexpr (std::is_same_v<E, NodeEnter>) {
                s.node = e;
                s.nodesEntered.push_back(e.node);
            } else if constexpr (std::is_same_v<E, NodeSkip>) {
                s.nodesSkipped.push_back(e.node);
            } else if constexpr (std::is_same_v<E, BuildNode>) {
                s.buildNode = e;
                s.candidates.clear();
                s.chosen.reset();
                ++s.nodesBuilt;
            } else if constexpr (std::is_same_v<E, SplitCandidate>) {
                s.candidates.push_back(e);
            } else if constexpr (std::is_same_v<E, SplitChosen>) {
                s.chosen = e;
            } else if constexpr (std::is_same_v<E, LeafMade>) {
                ++s.leavesMade;
                s.lastLeaf = e;
            } else if constexpr (std::is_same_v<E, RayHit>) {
                s.ray = e.ray;
                s.hit = e;
            } else if constexpr (std::is_same_v<E, RayBlocked>) {
                s.ray = e.ray;
                s.blocked = e;
            } else if constexpr (std::is_same_v<E, RayMiss>) {
                s.ray = e.ray;
                s.missed = true;
            } else if constexpr (std::is_same_v<E, ShadingTerm>) {
                if (!s.terms.empty() && s.terms.front().ray != e.ray) s.terms.clear();
                s.terms.push_back(e);
            } else if constexpr (std::is_same_v<E, PixelResult>) {
                s.pixel = e;
            }
        },
        event);
}

namespace {
/// What a copy of a state holds, roughly, in bytes.
std::size_t bytesOf(const ReplayState& s) {
    const auto v = [](const auto& vec) { return vec.size() * sizeof(vec[0]); };
    return sizeof s + v(s.visitedCells) + v(s.tests) + v(s.mailboxSkips) + v(s.nodesEntered) +
           v(s.nodesSkipped) + v(s.candidates) + v(s.terms);
}
}  // namespace

Replay::Replay(const EventLog& log) : log_(&log) {
    // One pass keeps a state every every_ events (and the state at 0); past the byte budget
    // every other checkpoint goes and the spacing doubles, so memory stays bounded.
    ReplayState s;
    checkpoints_.push_back(s);
    std::size_t bytes = bytesOf(s);
    const auto& events = log.events();
    for (std::size_t i = 0; i < events.size(); ++i) {
        applyEvent(s, events[i]);
        if (s.cursor % every_ != 0) continue;
        checkpoints_.push_back(s);
        bytes += bytesOf(s);
        while (bytes > kCheckpointBytes && checkpoints_.size() > 2) {
            std::vector<ReplayState> kept;
            bytes = 0;
            for (std::size_t k = 0; k < checkpoints_.size(); k += 2) {
                bytes += bytesOf(checkpoints_[k]);
                kept.push_back(std::move(checkpoints_[k]));
            }
            checkpoints_ = std::move(kept);
            every_ *= 2;
        }
    }
}

const ReplayState& Replay::seek(std::size_t cursor) {
    cursor = std::min(cursor, size());
    // Forward from where we are when that is near; otherwise from the checkpoint below.
    if (cursor < state_.cursor || cursor - state_.cursor > every_)
        state_ = checkpoints_[std::min(cursor / every_, checkpoints_.size() - 1)];
    const auto& events = log_->events();
    while (state_.cursor < cursor) applyEvent(state_, events[state_.cursor]);
    return state_;
}

std::size_t Replay::nextOfKind(std::size_t from, std::size_t kind) const {
    const auto& events = log_->events();
    for (std::size_t i = from; i < events.size(); ++i)
        if (events[i].index() == kind) return i;
    return events.size();
}

std::size_t Replay::previousOfKind(std::size_t from, std::size_t kind) const {
    const auto& events = log_->events();
    for (std::size_t i = std::min(from, events.size()); i-- > 0;)
        if (events[i].index() == kind) return i;
    return size();
}

}  // namespace raystep

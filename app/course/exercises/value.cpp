// value: one number read from the next event of its quantity's kind (tMax, tDelta, t_enter,
// a hit's t, u or v, a node's interval, a split candidate's probabilities and cost); a wrong
// number names the slip it betrays, read from the trace around that event.
#include "course/exercises/kind_unit.h"

#include "course/feedback_text.h"

#include "raystep/base/i18n.h"
#include "raystep/trace/event_text.h"

#include <cmath>

namespace raystep::exercises {

using feedback::axisName;

namespace {

/// Every quantity's name, as the lesson format writes them.
std::string quantityNames() {
    std::string names;
    for (int q = 0; q <= static_cast<int>(Quantity::CandidateCost); ++q)
        names += (names.empty() ? "" : ", ") + std::string(quantityName(static_cast<Quantity>(q)));
    return names;
}

/// The slip a wrong Value betrays, read from the trace around its source event.
std::string valueSlip(const Context& c, double given, double right, std::size_t source,
                      Language lang) {
    const auto n = [&](double v) { return formatNumber(v, lang); };
    const Quantity q = c.ex.quantity;
    const auto near = [&](double v) { return close(given, v, c.ex.tolerance); };
    const auto negativeAlong = [&](int axis) {
        const auto* setup = std::get_if<DdaSetup>(&c.log.events()[source]);
        return setup && setup->ray < c.log.rays().size() && c.log.rays()[setup->ray].dir[axis] < 0;
    };
    if (q >= Quantity::TDeltaX && q <= Quantity::TDeltaZ && right != 0.0 && near(-right) &&
        negativeAlong(static_cast<int>(q) - static_cast<int>(Quantity::TDeltaX)))
        return trf(lang,
                   "%1 is cell size / d without the abs: d is negative along this axis, but "
                   "tDelta is a distance along the ray, cell size / |d|.",
                   {n(given)});
    if (q >= Quantity::TMaxX && q <= Quantity::TMaxZ) {
        const auto* cell = std::get_if<DdaCell>(&c.log.events()[source]);
        const int axis = static_cast<int>(q) - static_cast<int>(Quantity::TMaxX);
        for (int k = 0; cell && k < c.log.dims(); ++k)
            if (k != axis && near(cell->tMax[k]))
                return trf(lang, "%1 is tMax.%2, not tMax.%3.",
                           {n(given), axisName(k), axisName(axis)});
        if (const auto setup = previousEvent<DdaSetup>(c.log, source); setup) {
            const double delta = setup->tDelta[axis];
            if (near(right - delta))
                return trf(lang,
                           "%1 is the tMax.%2 of the cell before: after a step along %2, tMax.%2 "
                           "grows by tDelta.%2 = %3.",
                           {n(given), axisName(axis), n(delta)});
        }
        // One step too far: the next cell's tMax, once the walk has left this one.
        if (const auto next = cell ? nextEvent<DdaCell>(c.log, source + 1) : std::nullopt;
            next && next->second.ray == cell->ray && next->second.tMax[axis] != right &&
            near(next->second.tMax[axis]))
            return trf(lang,
                       "%1 is tMax.%2 one step later, once the walk has left this cell: in %3, "
                       "tMax.%2 is where the ray crosses this cell's own far %2 boundary.",
                       {n(given), axisName(axis), cellText(cell->cell, c.log.dims())});
    }
    if (q == Quantity::HitU || q == Quantity::HitV) {
        const auto* hit = std::get_if<RayHit>(&c.log.events()[source]);
        const double other = hit ? (q == Quantity::HitU ? hit->v : hit->u) : right;
        if (hit && other != right && near(other))
            return q == Quantity::HitU
                       ? trf(lang,
                             "%1 is v, not u: u weighs corner b, v corner c (p = (1 − u − v) a + "
                             "u b + v c).",
                             {n(given)})
                       : trf(lang,
                             "%1 is u, not v: u weighs corner b, v corner c (p = (1 − u − v) a + "
                             "u b + v c).",
                             {n(given)});
    }
    if (q == Quantity::HitT || q == Quantity::TestT) {
        const auto* hit = std::get_if<RayHit>(&c.log.events()[source]);
        const auto* test = std::get_if<PrimitiveTest>(&c.log.events()[source]);
        if (hit || test) {
            const std::uint32_t ray = hit ? hit->ray : test->ray;
            const std::uint32_t prim = hit ? hit->prim : test->prim;
            if (const std::string s = rootSlip(c, given, right, ray, prim, lang); !s.empty())
                return s;
        }
    }
    if (q == Quantity::HitT) {
        // The slide's grid loop stops at the first hit found: a farther one, when cells overlap.
        const auto* hit = std::get_if<RayHit>(&c.log.events()[source]);
        for (std::size_t i = 0; hit && i < source; ++i)
            if (const auto* t = std::get_if<PrimitiveTest>(&c.log.events()[i]);
                t && t->ray == hit->ray && t->hit && t->prim != hit->prim && near(t->t))
                return trf(lang,
                           "%1 is primitive %2's intersection: found before the nearest one but "
                           "farther along the ray. Stopping at the first intersection found (the "
                           "slide's `break`) gives it; the nearest is primitive %3's.",
                           {n(given), std::to_string(t->prim), std::to_string(hit->prim)});
    }
    if (q == Quantity::NodeTNear || q == Quantity::NodeTFar) {
        const auto* e = std::get_if<NodeEnter>(&c.log.events()[source]);
        if (e && near(q == Quantity::NodeTNear ? e->tFar : e->tNear))
            return trf(lang, "%1 is the other end of the node's interval: tNear ≤ tFar.",
                       {n(given)});
    }
    if (q == Quantity::CandidatePL || q == Quantity::CandidatePR) {
        const auto* s = std::get_if<SplitCandidate>(&c.log.events()[source]);
        if (s && near(q == Quantity::CandidatePL ? s->pr : s->pl))
            return trf(lang, "%1 is the other side's probability: P(L|C) belongs to the left box.",
                       {n(given)});
        if (s && near(right * right))
            return trf(lang,
                       "%1 takes the probability as Area²/Area² (the slide's slip): P(L|C) is "
                       "Area(L) / Area(C), not squared.",
                       {n(given)});
    }
    if (right != 0.0 && near(-right)) return trf(lang, "%1 has the wrong sign.", {n(given)});
    return "";
}

class Value final : public OneNumberUnit {
  public:
    ExerciseKind kind() const override { return ExerciseKind::Value; }
    std::string_view name() const override { return "value"; }
    std::vector<const char*> keys() const override { return {"quantity"}; }

    void read(const LessonReader& r, const detail::json& j, const std::string& path,
              Exercise& ex) const override {
        if (!j.contains("quantity")) r.fail(path, "a value exercise names its \"quantity\"");
        const std::string p = JsonLineMap::child(path, "quantity");
        const auto q = parseQuantity(r.string(j["quantity"], p));
        if (!q) r.fail(p, "unknown quantity (expected one of " + quantityNames() + ")");
        ex.quantity = *q;
    }

    Reference reference(const Context& c, Language lang) const override {
        Reference ref;
        Answer& a = ref.answer;
        std::string& why = ref.why;
        const EventLog& log = c.log;
        const auto n = [&](double v) { return formatNumber(v, lang); };
        const Quantity q = c.ex.quantity;
        double v = 0.0;
        if (q >= Quantity::TMaxX && q <= Quantity::TMaxZ) {
            const auto e = nextEvent<DdaCell>(log, c.at);
            if (!e) c.fail("no DDA cell follows its position");
            const int axis = static_cast<int>(q) - static_cast<int>(Quantity::TMaxX);
            v = e->second.tMax[axis];
            ref.source = e->first;
            if (e->second.ray < log.rays().size() && std::isfinite(v)) {
                const RayRecord& r = log.rays()[e->second.ray];
                const double o = r.origin[axis], d = r.dir[axis];
                why = trf(lang,
                          "tMax.%1 is the t at which the ray crosses the next %1 boundary "
                          "after cell %2: (%3 − %4) / %5 = %6.",
                          {axisName(axis), cellText(e->second.cell, log.dims()), n(o + v * d), n(o),
                           n(d), n(v)});
            }
        } else if (q >= Quantity::TDeltaX && q <= Quantity::TExit) {
            const auto e = nextEvent<DdaSetup>(log, c.at);
            if (!e) c.fail("no DDA set-up follows its position");
            ref.source = e->first;
            if (q == Quantity::TEnter) {
                v = e->second.tEnter;
                why = trf(lang,
                          "t_enter is where the ray enters the grid: the largest of the slabs' "
                          "entry times, or 0 when the origin is inside: %1.",
                          {n(v)});
            } else if (q == Quantity::TExit) {
                v = e->second.tGridExit;
                why = trf(lang,
                          "t_exit is where the ray leaves the grid: the smallest of the slabs' "
                          "exit times: %1.",
                          {n(v)});
            } else {
                const int axis = static_cast<int>(q) - static_cast<int>(Quantity::TDeltaX);
                v = e->second.tDelta[axis];
                if (e->second.ray < log.rays().size() && std::isfinite(v)) {
                    const double d = log.rays()[e->second.ray].dir[axis];
                    why = trf(lang,
                              "tDelta.%1 is the t the ray takes to cross one cell along %1: "
                              "cell size / |d.%1| = %2 / |%3| = %4.",
                              {axisName(axis), n(v * std::abs(d)), n(d), n(v)});
                }
            }
        } else if (q >= Quantity::HitT && q <= Quantity::HitV) {
            const auto e = nextEvent<RayHit>(log, c.at);
            if (!e) c.fail("no hit follows its position");
            ref.source = e->first;
            v = q == Quantity::HitT ? e->second.t : q == Quantity::HitU ? e->second.u : e->second.v;
            why =
                q == Quantity::HitT
                    ? trf(lang,
                          "The nearest intersection of the ray is with primitive %1, at t = "
                          "%2.",
                          {std::to_string(e->second.prim), n(v)})
                    // Only the coordinate asked: the other may be the next exercise's.
                    : trf(lang,
                          "On primitive %1 the intersection has the barycentric coordinate "
                          "%2 = %3 (the point is (1 − u − v) a + u b + v c).",
                          {std::to_string(e->second.prim), q == Quantity::HitU ? "u" : "v", n(v)});
        } else if (q == Quantity::TestT) {
            std::optional<std::pair<std::size_t, PrimitiveTest>> hit;
            for (std::size_t i = c.at; i < log.events().size() && !hit; ++i)
                if (const auto* t = std::get_if<PrimitiveTest>(&log.events()[i]); t && t->hit)
                    hit = std::pair{i, *t};
            if (!hit) c.fail("no primitive test that hits follows its position");
            v = hit->second.t;
            ref.source = hit->first;
            why = feedback::hitOrMiss(lang, hit->second);
        } else if (q == Quantity::NodeTNear || q == Quantity::NodeTFar) {
            const auto e = nextEvent<NodeEnter>(log, c.at);
            if (!e) c.fail("no node is entered after its position");
            ref.source = e->first;
            v = q == Quantity::NodeTNear ? e->second.tNear : e->second.tFar;
            why = trf(lang,
                      "Node %1 is entered over [tNear, tFar] = [%2, %3]: the part of the ray "
                      "inside its box (the slab test), clipped to the parent's.",
                      {std::to_string(e->second.node), n(e->second.tNear), n(e->second.tFar)});
        } else {
            const auto e = nextEvent<SplitCandidate>(log, c.at);
            if (!e) c.fail("no split candidate follows its position");
            ref.source = e->first;
            const SplitCandidate& s = e->second;
            v = q == Quantity::CandidatePL ? s.pl : q == Quantity::CandidatePR ? s.pr : s.sahCost;
            why = trf(lang,
                      "Candidate %1 = %2: NL = %3, NR = %4, P(L|C) = Area(L) / Area(C) = %5, "
                      "P(R|C) = %6, cost = C_trav + C_isect (P(L|C) NL + P(R|C) NR) = %7.",
                      {axisName(s.axis), n(s.position), std::to_string(s.nl), std::to_string(s.nr),
                       n(s.pl), n(s.pr), n(s.sahCost)});
        }
        if (!std::isfinite(v)) c.fail("the trace's value is not finite (the ray never crosses)");
        a.numbers.push_back(v);
        return ref;
    }

    std::string slip(const Context& c, const Answer& given, const Reference& ref,
                     const std::string&, Language lang) const override {
        return valueSlip(c, given.numbers[0], ref.answer.numbers[0], *ref.source, lang);
    }

    std::string retryAdvice(const Exercise& ex, bool replayHeld, Language lang) const override {
        if (!replayHeld) return stepTheReplayAdvice(lang);
        if (heldAtTheStart(ex))
            return tr(lang,
                      "The replay waits at the start until you answer: put the numbers the "
                      "exercise gives into the formula.");
        return tr(lang,
                  "The replay waits here until you answer: put the ray's "
                  "numbers from the inspector into the formula.");
    }

    // A text line, not a number box: the app has always let a value be typed freely.
    std::string placeholder(const Exercise&, int, Language lang) const override {
        return tr(lang, "a number, e.g. 1.25");
    }

    void answerForms(const LeakInput& in, AnswerForms& f) const override {
        const Answer a = referenceAnswer(in.ex, in.log, in.file, in.sweep);
        addLeakNumber(f, a.numbers.at(0));
        f.describe = formatNumber(a.numbers[0]);
    }
};

}  // namespace

const ExerciseKindUnit& valueUnit() {
    static const Value unit;
    return unit;
}

}  // namespace raystep::exercises

// Exercises: answers as typed, the right answer read from the recorded trace (never from the
// lesson file), and the check of a student's answer with the trace's explanation.
#include "course/exercise.h"

#include "feedback_text.h"

#include "raystep/base/format.h"
#include "raystep/trace/event_text.h"

#include "course/lesson_trace.h"

#include "raystep/base/math.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace raystep {

using feedback::axisName;

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
            const int dims = log.dims();
            for (int i = 0; i < dims; ++i) a.numbers.push_back(next->second.cell[i]);
            why = feedback::nextCell(lang, previousEvent<DdaCell>(log, next->first), next->second,
                                     dims);
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
                source = "dda_cell " + cellText(e->second.cell, log.dims());
            } else if (q >= Quantity::TDeltaX && q <= Quantity::TExit) {
                const auto e = nextEvent<DdaSetup>(log, c.at);
                if (!e) c.fail("no DDA set-up follows its position");
                v = q == Quantity::TEnter ? e->second.tEnter
                    : q == Quantity::TExit
                        ? e->second.tGridExit
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
                         formatNumber(s.position) + " (NL " + std::to_string(s.nl) + ", NR " +
                         std::to_string(s.nr) + ", P(L|C) " + formatNumber(s.pl) + ", P(R|C) " +
                         formatNumber(s.pr) + ", cost " + formatNumber(s.sahCost) + ")";
            }
            if (!std::isfinite(v))
                c.fail("the trace's value is not finite (the ray never crosses)");
            a.numbers.push_back(v);
            why = feedback::value(lang, q, v, source);
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
            why = feedback::pickSplit(lang, count, node->second.node, *best);
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
            // What was counted, e.g. "ray_begin shadow depth 1" (appended piece by piece: GCC 12
            // warns, falsely, with -Wrestrict on " " + string here).
            std::string what(kEventNames[c.ex.countKind]);
            if (c.ex.rayKind) {
                what += ' ';
                what += kRayKindNames[static_cast<int>(*c.ex.rayKind)];
            }
            if (c.ex.rayDepth) {
                what += " depth ";
                what += std::to_string(*c.ex.rayDepth);
            }
            why = feedback::count(lang, n, what, c.ex.at,
                                  c.ex.until.value_or(ReplayPosition{ReplayPosition::Mode::End}));
            break;
        }
        case ExerciseKind::HitOrMiss: {
            const auto t = nextEvent<PrimitiveTest>(log, c.at);
            if (!t) c.fail("no primitive test follows its position");
            a.hit = t->second.hit;
            if (t->second.hit && c.ex.withT) a.numbers.push_back(t->second.t);
            why = feedback::hitOrMiss(lang, t->second);
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
            // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on "," + to_string here.
            for (std::size_t i = 0; i < a.numbers.size(); ++i) {
                if (i) s += ',';
                s += std::to_string(static_cast<long long>(a.numbers[i]));
            }
            return s;
        }
        case ExerciseKind::Value:
            return a.numbers.empty() ? "" : formatNumber(a.numbers[0]);
        case ExerciseKind::Count:
            return a.numbers.empty() ? "" : std::to_string(static_cast<long long>(a.numbers[0]));
        case ExerciseKind::PickSplit:
            return a.numbers.size() < 2 ? ""
                                        : std::string(axisName(static_cast<int>(a.numbers[0]))) +
                                              "=" + formatNumber(a.numbers[1]);
        case ExerciseKind::HitOrMiss:
            if (!a.hit) return "";
            if (!*a.hit) return "miss";
            return a.numbers.empty() ? "hit" : "hit " + formatNumber(a.numbers[0]);
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

}  // namespace raystep

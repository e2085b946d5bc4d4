// spot_bug exercises (app/course/exercises/spot_bug.cpp): the first wrong step of a replayed DDA
// walk with one classic mistake in it. The expected step is recomputed here with an exact walk of
// the test's own, in rational arithmetic (no raystep walk), over hundreds of seeded rays and grids
// for every DDA mistake; then the grading and its feedback in both languages, and the built-in
// lessons' spot_bug exercises, answerable from their own traces.
#include "course/exercise.h"
#include "course/exercises/kind_unit.h"
#include "course/grading.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"

#include "raystep/assess/mistakes.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace raystep {
namespace {

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// ---- an exact rational walk, the test's own ----

using Int = long long;  // ample: the numbers are small dyadic ones, reduced at every step

Int gcdOf(Int a, Int b) {
    if (a < 0) a = -a;
    if (b < 0) b = -b;
    while (b != 0) {
        const Int t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/// n / d, reduced, d > 0.
struct Q {
    Int n = 0, d = 1;
    Q() = default;
    Q(Int num, Int den) : n(num), d(den) {
        if (d < 0) n = -n, d = -d;
        const Int g = gcdOf(n, d);
        if (g > 1) n /= g, d /= g;
    }
    explicit Q(long long v) : n(v), d(1) {}
};
Q operator+(Q a, Q b) {
    return {a.n * b.d + b.n * a.d, a.d * b.d};
}
Q operator-(Q a, Q b) {
    return {a.n * b.d - b.n * a.d, a.d * b.d};
}
Q operator*(Q a, Q b) {
    return {a.n * b.n, a.d * b.d};
}
Q operator/(Q a, Q b) {
    return {a.n * b.d, a.d * b.n};
}
bool operator<(Q a, Q b) {
    return a.n * b.d < b.n * a.d;
}
bool operator==(Q a, Q b) {
    return a.n == b.n && a.d == b.d;
}
bool operator<=(Q a, Q b) {
    return !(b < a);
}

/// A grid and a ray in exact numbers: lo + k size on each axis, o + t d.
struct Case {
    int dims = 2;
    std::array<Q, 3> lo, size, o, d;
    std::array<int, 3> res{1, 1, 1};
    std::array<bool, 3> negativeZero{false, false, false};  // d[a] is -0.0
    double at(const Q& q) const { return double(q.n) / double(q.d); }
};

/// Amanatides & Woo's walk from t = 0, exactly: the first cell holds the point just after the
/// grid is entered, each step crosses the nearest boundary (every tied axis at once), and the
/// walk ends when that boundary is at or beyond the grid's exit.
std::vector<std::array<int, 3>> exactWalk(const Case& c) {
    const int n = c.dims;
    Q tEnter(0);
    std::optional<Q> tExit;
    const auto crossing = [&](int a, long long k) {
        return (c.lo[a] + Q(k) * c.size[a] - c.o[a]) / c.d[a];
    };
    for (int a = 0; a < n; ++a) {
        const Q hi = c.lo[a] + Q(c.res[a]) * c.size[a];
        if (c.d[a].n == 0) {
            if (c.o[a] < c.lo[a] || hi < c.o[a]) return {};
            continue;
        }
        Q t0 = (c.lo[a] - c.o[a]) / c.d[a], t1 = (hi - c.o[a]) / c.d[a];
        if (t1 < t0) std::swap(t0, t1);
        if (tEnter < t0) tEnter = t0;
        if (!tExit || t1 < *tExit) tExit = t1;
    }
    if (tExit && !(tEnter < *tExit)) return {};
    std::array<int, 3> cell{0, 0, 0};
    for (int a = 0; a < n; ++a) {
        for (int k = 0; k < c.res[a]; ++k) {
            const bool holds = c.d[a].n == 0  ? c.lo[a] + Q(k) * c.size[a] <= c.o[a]
                               : c.d[a].n > 0 ? crossing(a, k) <= tEnter
                                              : tEnter < crossing(a, k);
            if (holds) cell[a] = k;
        }
    }
    std::vector<std::array<int, 3>> walk{cell};
    for (;;) {
        std::optional<Q> next;
        std::array<Q, 3> tMax;
        for (int a = 0; a < n; ++a) {
            if (c.d[a].n == 0) continue;
            tMax[a] = crossing(a, c.d[a].n > 0 ? cell[a] + 1 : cell[a]);
            if (!next || tMax[a] < *next) next = tMax[a];
        }
        if (!next || (tExit && *tExit <= *next)) break;
        bool out = false;
        for (int a = 0; a < n; ++a) {
            if (c.d[a].n == 0 || !(tMax[a] == *next)) continue;
            cell[a] += c.d[a].n > 0 ? 1 : -1;
            out = out || cell[a] < 0 || cell[a] >= c.res[a];
        }
        if (out) break;
        walk.push_back(cell);
    }
    return walk;
}

/// A seeded case: dyadic numbers, so the doubles the code under test reads are these exactly;
/// some rays through grid vertices (ties), along an axis (a zero, or a negative zero), or from
/// outside the grid.
Case drawCase(std::mt19937& rng, int dims) {
    const auto pick = [&](int lo, int hi) {
        return std::uniform_int_distribution<int>(lo, hi)(rng);
    };
    Case c;
    c.dims = dims;
    const int kind = pick(0, 9);
    for (int a = 0; a < dims; ++a) {
        c.lo[a] = Q(pick(-3, 3));
        c.size[a] = Q(pick(2, 8), 4);
        c.res[a] = pick(1, 9);
        const Q span = Q(c.res[a]) * c.size[a];
        // The origin: inside, or up to 2 cells' worth outside, in 16ths.
        const Q margin = kind >= 7 ? Q(2) : Q(0);
        const Int lo16 = ((c.lo[a] - margin) * Q(16)).n,
                  hi16 = ((c.lo[a] + span + margin) * Q(16)).n;
        c.o[a] = Q(
            std::uniform_int_distribution<long long>(lo16, static_cast<long long>(hi16))(rng), 16);
        c.d[a] = Q(pick(-16, 16), 8);
    }
    if (kind <= 1) {
        // Through a vertex: equal crossing rates and equal offsets from a boundary.
        const Q off = Q(pick(0, 3), 16);
        for (int a = 0; a < dims; ++a) {
            c.size[a] = c.size[0];
            c.o[a] = c.lo[a] + Q(pick(0, c.res[a] - 1)) * c.size[a] + off;
            c.d[a] = Q(pick(0, 1) ? 1 : -1);
        }
    } else if (kind == 2) {
        const int a = pick(0, dims - 1);
        c.d[a] = Q(0);
        c.negativeZero[a] = pick(0, 1) == 1;
    }
    bool zero = true;
    for (int a = 0; a < dims; ++a) zero = zero && c.d[a].n == 0;
    if (zero) c.d[0] = Q(1);
    return c;
}

template <int N>
std::vector<WalkCell<N>> wrongWalk(const Case& c, Mistake m, int cap) {
    GridSpec<N, double> grid;
    VecN<N, double> o, d;
    for (int a = 0; a < N; ++a) {
        grid.lo[a] = c.at(c.lo[a]);
        grid.hi[a] = c.at(c.lo[a] + Q(c.res[a]) * c.size[a]);
        grid.res[a] = c.res[a];
        o[a] = c.at(c.o[a]);
        d[a] = c.negativeZero[a] ? -0.0 : c.at(c.d[a]);
    }
    return ddaWithMistake<N>(grid, o, d, m, cap);
}

/// The first step of the wrong walk whose cell is not the exact walk's (one past its end
/// included); nullopt when there is none (the same walk, or one that only stops early).
template <int N>
std::optional<std::size_t> firstWrongStep(const Case& c, Mistake m) {
    int cap = N + 1;
    for (int a = 0; a < N; ++a) cap += c.res[a];
    const auto wrong = wrongWalk<N>(c, m, cap);
    const auto exact = exactWalk(c);
    for (std::size_t k = 0; k < wrong.size(); ++k) {
        if (k >= exact.size()) return k;
        for (int a = 0; a < N; ++a)
            if (wrong[k].cell[a] != exact[k][a]) return k;
    }
    return std::nullopt;
}

// ---- the code under test, on a case ----

Exercise spotBug(Mistake m) {
    Exercise ex;
    ex.id = "spot";
    ex.kind = ExerciseKind::SpotBug;
    ex.mistake = std::string(mistakeInfo(m).name);
    return ex;
}

EventLog recorded(const Exercise& ex, const Case& c) {
    GridRecord g{{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {1, 1, 1}};
    WalkRay ray;
    ray.dims = c.dims;
    for (int a = 0; a < c.dims; ++a) {
        g.lo[a] = c.at(c.lo[a]);
        g.hi[a] = c.at(c.lo[a] + Q(c.res[a]) * c.size[a]);
        g.res[a] = c.res[a];
        ray.o[a] = c.at(c.o[a]);
        ray.d[a] = c.negativeZero[a] ? -0.0 : c.at(c.d[a]);
    }
    EventLog log;
    exercises::unitOf(ExerciseKind::SpotBug).recordWalk(ex, g, c.dims, ray, log);
    return log;
}

TEST(SpotBug, TheAnswerIsTheFirstWrongStepOfAnExactWalkOfItsOwn) {
    std::mt19937 rng(31);
    std::map<std::string, int> diverged;
    int cases = 0;
    for (int i = 0; i < 600; ++i) {
        const int dims = i % 2 ? 3 : 2;
        const Case c = drawCase(rng, dims);
        for (const MistakeInfo& info : mistakes()) {
            if (!info.dda) continue;
            SCOPED_TRACE("case " + std::to_string(i) + " " + std::string(info.name));
            const Exercise ex = spotBug(info.mistake);
            const EventLog log = recorded(ex, c);
            const auto expected =
                dims == 2 ? firstWrongStep<2>(c, info.mistake) : firstWrongStep<3>(c, info.mistake);
            std::optional<double> computed;
            try {
                computed = referenceAnswer(ex, log, "t.json").numbers.at(0);
            } catch (const LessonError& e) {
                // No wrong cell: a validation error naming the exercise.
                EXPECT_EQ(e.key(), "exercises.spot") << e.what();
            }
            ++cases;
            ASSERT_EQ(computed.has_value(), expected.has_value())
                << (computed ? *computed : -1.0) << " vs " << (expected ? int(*expected) : -1);
            if (!expected) continue;
            EXPECT_EQ(*computed, double(*expected));
            ++diverged[std::string(info.name)];
            // The replay shows the wrong walk's cells up to that step, the answer's among them.
            const auto wrong2 =
                dims == 2 ? wrongWalk<2>(c, info.mistake, 64) : std::vector<WalkCell<2>>{};
            const auto wrong3 =
                dims == 3 ? wrongWalk<3>(c, info.mistake, 64) : std::vector<WalkCell<3>>{};
            std::size_t k = 0;
            for (const Event& e : log.events()) {
                const auto* dc = std::get_if<DdaCell>(&e);
                if (!dc || k > *expected) continue;
                for (int a = 0; a < dims; ++a)
                    EXPECT_EQ(dc->cell[a], dims == 2 ? wrong2.at(k).cell[a] : wrong3.at(k).cell[a]);
                ++k;
            }
            EXPECT_GT(k, *expected);
        }
    }
    EXPECT_EQ(cases, 600 * 8);
    // Every mistake but the rounding one goes wrong on many of these rays: the check is not empty.
    for (const MistakeInfo& info : mistakes()) {
        if (!info.dda || info.mistake == Mistake::AccumulatedTmax) continue;
        EXPECT_GE(diverged[std::string(info.name)], 15) << info.name;
    }
}

// ---- the built-in lessons' exercises ----

struct Built {
    Lesson lesson;
    std::shared_ptr<LessonRun> run;
};
const Built& built(const std::string& id) {
    static std::map<std::string, Built> runs;
    auto it = runs.find(id);
    if (it == runs.end()) {
        Lesson l = loadLesson(id);
        auto run = std::make_shared<LessonRun>(runLesson(l));
        it = runs.emplace(id, Built{std::move(l), std::move(run)}).first;
    }
    return it->second;
}

Verdict verdictFor(const std::string& lesson, const std::string& typed, Language lang) {
    const Built& b = built(lesson);
    const Exercise& ex = *b.lesson.exercise("spot-the-bug");
    std::string why;
    const auto answer = parseAnswer(ex, typed, &why, lang);
    EXPECT_TRUE(answer) << typed << ": " << why;
    if (!answer) return {};
    return checkAnswer(ex, b.run->logs().of(ex.setup), *answer, lang, b.lesson.file, nullptr,
                       b.run->scene.get());
}

TEST(SpotBug, LessonSixGradesTheStepOrTheClickedCellAndNamesTheQuantity) {
    // o = (5.3, 0.4), d = (-0.9, 0.3) with tMax set up from X + 1: tMaxX = (6 - 5.3) / -0.9 =
    // -7/9 instead of (5 - 5.3) / -0.9 = 1/3. Three steps in X, (4, 0), (3, 0), (2, 0), where the
    // exact walk steps in Y from (3, 0): tMaxY = 2 < tMaxX = 1/3 + 2 (10/9) = 23/9.
    const Verdict right = verdictFor("6", "3", Language::En);
    EXPECT_TRUE(right.correct);
    EXPECT_TRUE(has(right.feedback,
                    "At step 3 the replayed walk enters its first wrong cell, "
                    "(2, 0); the exact walk enters (3, 1)."))
        << right.feedback;
    EXPECT_TRUE(has(right.feedback, "tMaxY = 2 and tMaxX = 2.55556: tMaxY < tMaxX"))
        << right.feedback;
    EXPECT_TRUE(has(right.feedback, "negative-direction-boundary")) << right.feedback;
    EXPECT_TRUE(verdictFor("6", "2,0", Language::En).correct);  // the cell, as clicked
    EXPECT_TRUE(verdictFor("6", "(2, 0)", Language::It).correct);

    const Verdict early = verdictFor("6", "0", Language::En);
    EXPECT_FALSE(early.correct);
    EXPECT_TRUE(has(early.slip, "its tMaxX = -0.777778 is not the exact 0.333333")) << early.slip;
    const Verdict late = verdictFor("6", "5", Language::En);
    EXPECT_FALSE(late.correct);
    EXPECT_TRUE(has(late.slip, "not the first wrong one")) << late.slip;
    EXPECT_FALSE(verdictFor("6", "3,1", Language::En).correct);
    EXPECT_TRUE(has(verdictFor("6", "9", Language::En).slip, "steps 0 to 6 only"));

    const Verdict it = verdictFor("6", "1", Language::It);
    EXPECT_FALSE(it.correct);
    EXPECT_TRUE(has(it.slip, "il suo tMaxX = 0,333333 però non è quello esatto, 1,44444"))
        << it.slip;
    EXPECT_TRUE(has(it.feedback, "tMaxY = 2 e tMaxX = 2,55556: tMaxY < tMaxX")) << it.feedback;
    EXPECT_TRUE(has(it.feedback,
                    "Al passo 3 l'attraversamento riprodotto entra nella sua prima "
                    "cella sbagliata"))
        << it.feedback;
    EXPECT_TRUE(has(it.feedback, "L'errore, negative-direction-boundary: tMax è inizializzato"))
        << it.feedback;
    std::string why;
    EXPECT_FALSE(
        parseAnswer(*built("6").lesson.exercise("spot-the-bug"), "tre", &why, Language::It));
    EXPECT_TRUE(has(why, "il numero di un passo")) << why;
}

TEST(SpotBug, LessonSevenStartsInTheEyesVoxelAndSaysTEnter) {
    // The eye (2.6, 3.4, 5.2) clamped into the grid is voxel (3, 1, 3); the ray enters through
    // z = 2 at t_enter = 3.2 / 0.797, in (2, 1, 3): the first step is already wrong.
    const Verdict right = verdictFor("7", "0", Language::En);
    EXPECT_TRUE(right.correct);
    EXPECT_TRUE(has(right.feedback,
                    "Your first cell is (3, 1, 3), but the walk starts in "
                    "(2, 1, 3), the cell where the ray enters the grid, at tEnter"))
        << right.feedback;
    EXPECT_TRUE(has(right.feedback, "no-entry-clip")) << right.feedback;
    const Verdict it = verdictFor("7", "2", Language::It);
    EXPECT_FALSE(it.correct);
    EXPECT_TRUE(has(it.feedback, "a tEnter = 4,01512")) << it.feedback;
}

TEST(SpotBug, TheLessonsExercisesAreAnswerableFromTheirOwnTraces) {
    for (const std::string id : {"6", "7"}) {
        SCOPED_TRACE(id);
        const Built& b = built(id);
        EXPECT_NO_THROW(validateLesson(b.lesson));
        const Exercise& ex = *b.lesson.exercise("spot-the-bug");
        ASSERT_TRUE(ex.setup);
        EXPECT_EQ(ex.setup->replay, ex.id);
        const EventLog& log = b.run->logs().of(ex.setup);
        // Its own trace, not the lesson's: one ray, its set-up, its cells, no test.
        EXPECT_NE(&log, b.run->log.get());
        ASSERT_EQ(log.rays().size(), 1u);
        ASSERT_TRUE(log.grid());
        int cells = 0, tests = 0;
        for (const Event& e : log.events()) {
            cells += std::holds_alternative<DdaCell>(e);
            tests += std::holds_alternative<PrimitiveTest>(e);
        }
        EXPECT_GT(cells, 3);
        EXPECT_EQ(tests, 0);
        EXPECT_TRUE(std::holds_alternative<RayBegin>(log.events().front()));
        EXPECT_TRUE(std::holds_alternative<RayMiss>(log.events().back()));
        // The replay is free: the student must see the whole wrong walk.
        EXPECT_FALSE(quizLimit(ex, log).has_value());
        EXPECT_FALSE(answerEventIndex(ex, log, b.lesson.file).has_value());
        const Answer ref = referenceAnswer(ex, log, b.lesson.file);
        ASSERT_EQ(ref.numbers.size(), 1u);
        EXPECT_LT(ref.numbers[0], cells);
        EXPECT_EQ(answerInput(ex).click, AnswerInputSpec::ViewClick::Fills);
    }
}

// ---- what a lesson file may ask ----

std::string lessonWith(const std::string& exercise, const std::string& setup = "\"grid\"") {
    return "{\"format\": \"raystep-lesson\", \"version\": 1, \"id\": \"t\", \"number\": 1,\n"
           "\"title\": {\"en\": \"T\"}, \"text\": {\"en\": \"x\"}, \"scene\": \"lecture-grid\",\n"
           "\"setup\": {\"accel\": " +
           setup + "}, \"trace\": {\"ray\": \"example\"},\n\"exercises\": [\n" + exercise + "]}";
}

TEST(SpotBug, AMistakeThatDoesNotGoWrongOnTheRayIsAnErrorNamingTheExercise) {
    // The slides' ray crosses no vertex: a tie's mistake walks it exactly.
    const Lesson l = loadLessonText(
        lessonWith("{\"id\": \"spot\", \"type\": \"spot_bug\", \"mistake\": \"tie-one-axis\", "
                   "\"prompt\": {\"en\": \"?\"}}"),
        "t.json");
    try {
        validateLesson(l);
        ADD_FAILURE() << "a walk without a wrong cell validates";
    } catch (const LessonError& e) {
        EXPECT_EQ(e.key(), "exercises.spot");
        EXPECT_TRUE(has(e.what(), "tie-one-axis walks this ray as the exact walk does"))
            << e.what();
    }
    // The example ray's own first cell is its origin's: skipping it goes wrong at step 0.
    const Lesson skip =
        loadLessonText(lessonWith("{\"id\": \"spot\", \"type\": \"spot_bug\", \"mistake\": "
                                  "\"start-cell-skipped\", \"prompt\": {\"en\": \"?\"}}"),
                       "t.json");
    const LessonRun run = runLesson(skip);
    EXPECT_EQ(referenceAnswer(skip.exercises[0], run.logs().of(skip.exercises[0].setup), "t.json")
                  .numbers,
              std::vector<double>{0.0});
}

TEST(SpotBug, ItsKeysAreChecked) {
    const auto message = [](const std::string& exercise, const std::string& setup = "\"grid\"") {
        try {
            loadLessonText(lessonWith(exercise, setup), "t.json");
        } catch (const LessonError& e) {
            return std::string(e.what());
        }
        return std::string("loads");
    };
    EXPECT_TRUE(has(message("{\"id\": \"s\", \"type\": \"spot_bug\", \"prompt\": {\"en\": \"?\"}}"),
                    "names its \"mistake\""));
    EXPECT_TRUE(has(message("{\"id\": \"s\", \"type\": \"spot_bug\", \"mistake\": \"no-mailbox\", "
                            "\"prompt\": {\"en\": \"?\"}}"),
                    "expected a mistake of the DDA walk: start-cell-skipped"));
    EXPECT_TRUE(has(message("{\"id\": \"s\", \"type\": \"spot_bug\", \"mistake\": "
                            "\"no-exit-check\", \"prompt\": {\"en\": \"?\"}}",
                            "\"bvh\""),
                    "must be grid"));  // the structure of cells
    EXPECT_TRUE(has(message("{\"id\": \"s\", \"type\": \"spot_bug\", \"mistake\": "
                            "\"no-exit-check\", \"ray\": {\"o\": [1, 2], \"d\": [0, 0]}, "
                            "\"prompt\": {\"en\": \"?\"}}"),
                    "must not be zero"));
    EXPECT_TRUE(has(message("{\"id\": \"s\", \"type\": \"value\", \"mistake\": \"no-exit-check\", "
                            "\"quantity\": \"tMax.x\", \"prompt\": {\"en\": \"?\"}}"),
                    "only spot_bug exercises take this key"));
    // A ray of its own, and -0.0 kept: the negative zero's mistake steps up along y.
    const Lesson l = loadLessonText(
        lessonWith("{\"id\": \"s\", \"type\": \"spot_bug\", \"mistake\": \"negative-zero\", "
                   "\"ray\": {\"o\": [0.5, 2.5], \"d\": [1, -0.0]}, \"prompt\": {\"en\": \"?\"}}"),
        "t.json");
    ASSERT_TRUE(l.exercises[0].walkRay);
    EXPECT_TRUE(std::signbit(l.exercises[0].walkRay->d[1]));
    const LessonRun run = runLesson(l);
    const EventLog& log = run.logs().of(l.exercises[0].setup);
    // (0, 2) then, with tMaxY = (3 - 2.5) / -0 = -inf, a step up to (0, 3): step 1.
    EXPECT_EQ(referenceAnswer(l.exercises[0], log, "t.json").numbers, std::vector<double>{1.0});
}

}  // namespace
}  // namespace raystep

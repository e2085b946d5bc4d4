// Running a lesson: load its scene, build its structure, record its trace; and finding the
// replay positions its steps and exercises name in that trace.
#include "course/lesson_trace.h"

#include "feedback_text.h"

#include "course/exercises/kind_unit.h"

#include "raystep/accel/dda_textbook.h"
#include "raystep/accel/outline.h"
#include "raystep/trace/event_text.h"

#include "raystep/render/tracer.h"
#include "raystep/scene/resources.h"
#include "raystep/scene/scene_loader.h"

#include <algorithm>
#include <filesystem>

namespace raystep {

std::string lessonScenePath(const Lesson& lesson) {
    // Where the lesson came from decides, not its path's text (a lecturer's lessons/my.json).
    if (lesson.builtin || embeddedFile(lesson.scene + ".json")) return lesson.scene;
    // A scene file next to the lesson file.
    const std::filesystem::path p(lesson.scene);
    if (p.is_absolute()) return lesson.scene;
    return (std::filesystem::path(lesson.file).parent_path() / p).string();
}

LessonLogs LessonRun::logs() const {
    LessonLogs l(*log);
    for (const LessonStructureRun& o : others) l.bySetup[o.setup.key()] = o.log.get();
    return l;
}

std::unique_ptr<EventLog> recordLessonTrace(const Lesson& lesson,
                                            const std::variant<Scene, Scene2D>& scene,
                                            const Accelerator* accel3D,
                                            const Accelerator2D* accel2D) {
    return recordLessonTrace(lesson, lesson.setup(), scene, accel3D, accel2D);
}

namespace {
/// The node boxes of a tree (outline.h) into `log`, 2D boxes at z = 0.
template <int N>
void recordNodeBoxes(const StructureOutline<N>& o, EventLog& log) {
    for (std::size_t id = 0; id < o.nodes.size(); ++id) {
        std::array<double, 3> lo{0.0, 0.0, 0.0}, hi{0.0, 0.0, 0.0};
        for (int a = 0; a < N; ++a) {
            lo[a] = o.nodes[id].box.lo[a];
            hi[a] = o.nodes[id].box.hi[a];
        }
        log.node(static_cast<std::uint32_t>(id), lo, hi);
    }
}
}  // namespace

namespace {
template <int N>
GridRecord gridRecord(const GridSpec<N, double>& spec) {
    GridRecord g{{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {1, 1, 1}};
    for (int a = 0; a < N; ++a) {
        g.lo[a] = spec.lo[a];
        g.hi[a] = spec.hi[a];
        g.res[a] = spec.res[a];
    }
    return g;
}

/// A spot_bug exercise's trace: its wrong walk of its ray (else the lesson's first ray) on the
/// structure's grid.
std::unique_ptr<EventLog> recordReplayedWalk(const Lesson& lesson, const LessonSetup& setup,
                                             const std::variant<Scene, Scene2D>& scene,
                                             const Accelerator* accel3D,
                                             const Accelerator2D* accel2D) {
    const Exercise* ex = lesson.exercise(setup.replay);
    if (!ex) throw LessonError(lesson.file, 0, "exercises", "no exercise " + setup.replay);
    const auto fail = [&](const std::string& message) {
        throw LessonError(lesson.file, ex->line, "exercises." + ex->id, message);
    };
    std::optional<GridRecord> grid;
    int dims = 3;
    if (accel2D) {
        dims = 2;
        if (const auto o = outline(*accel2D); o.grid) grid = gridRecord(o.grid->spec);
    } else if (accel3D) {
        if (const auto o = outline(*accel3D); o.grid) grid = gridRecord(o.grid->spec);
    }
    if (!grid) fail("its walk is replayed on a grid, and its structure is none");
    WalkRay ray;
    if (ex->walkRay) {
        ray = *ex->walkRay;
    } else {
        // The lesson's own first ray: the example ray, the trace's ray, a pixel's primary ray.
        LessonSetup plain = setup;
        plain.replay.clear();
        const auto own = recordLessonTrace(lesson, plain, scene, accel3D, accel2D);
        if (own->rays().empty()) fail("the lesson's trace has no ray: give the exercise a \"ray\"");
        const RayRecord& r = own->rays().front();
        ray.o = {r.origin.x, r.origin.y, r.origin.z};
        ray.d = {r.dir.x, r.dir.y, r.dir.z};
        ray.dims = dims;
    }
    if (ray.dims != dims)
        fail("its ray is " + std::to_string(ray.dims) + "D, the scene " + std::to_string(dims) +
             "D");
    auto log = std::make_unique<EventLog>();
    exercises::unitOf(ex->kind).recordWalk(*ex, *grid, dims, ray, *log);
    return log;
}
}  // namespace

std::unique_ptr<EventLog> recordLessonTrace(const Lesson& lesson, const LessonSetup& setup,
                                            const std::variant<Scene, Scene2D>& scene,
                                            const Accelerator* accel3D,
                                            const Accelerator2D* accel2D) {
    if (!setup.replay.empty()) return recordReplayedWalk(lesson, setup, scene, accel3D, accel2D);
    auto log = std::make_unique<EventLog>();
    const LessonTrace& t = lesson.trace;
    const auto* s2 = std::get_if<Scene2D>(&scene);
    const auto* s3 = std::get_if<Scene>(&scene);
    const auto fail = [&](const std::string& message) {
        throw LessonError(lesson.file, 0, "trace", message);
    };
    switch (t.kind) {
        case LessonTrace::Kind::Build:
            buildStructure(scene, setup.accel, {}, setup.options, log.get());
            break;
        case LessonTrace::Kind::ExampleRay:
        case LessonTrace::Kind::Ray2D: {
            if (!s2) fail("a 2D ray needs a 2D scene; " + printable(lesson.scene) + " is 3D");
            if (t.kind == LessonTrace::Kind::ExampleRay && !s2->exampleRay)
                fail("the scene " + printable(lesson.scene) + " has no example ray");
            traceRay2D(*accel2D, t.kind == LessonTrace::Kind::Ray2D ? t.ray : *s2->exampleRay,
                       *log);
            break;
        }
        case LessonTrace::Kind::Pixel:
            if (!s3) fail("a pixel needs a 3D scene; " + printable(lesson.scene) + " is 2D");
            tracePixelEvents(*s3, *accel3D, t.x, t.y, t.width, t.height, *log);
            break;
        case LessonTrace::Kind::Ray3D:
            if (!s3) fail("a 3D ray needs a 3D scene; " + printable(lesson.scene) + " is 2D");
            traceRay3D(*accel3D, t.ray3D, *log);
            break;
    }
    // An overlap exercise's answer is two of these boxes: the trace carries them (a build has
    // its own already).
    const bool overlap =
        std::any_of(lesson.exercises.begin(), lesson.exercises.end(),
                    [](const Exercise& e) { return exercises::unitOf(e.kind).needsNodeBoxes(); });
    if (overlap && t.kind != LessonTrace::Kind::Build) {
        if (accel2D) recordNodeBoxes(outline(*accel2D), *log);
        if (accel3D) recordNodeBoxes(outline(*accel3D), *log);
    }
    return log;
}

std::variant<Scene, Scene2D> loadLessonScene(const Lesson& lesson) {
    try {
        if (lesson.sceneText.empty()) return loadAnyScene(lessonScenePath(lesson));
        // Checked when the lesson was read: a failure here is the file changed since.
        if (isScene2DText(lesson.sceneText)) return loadScene2DText(lesson.sceneText, lesson.file);
        return loadSceneText(lesson.sceneText, lesson.file,
                             [](const std::string&) { return std::nullopt; });
    } catch (const SceneError& e) {
        throw LessonError(lesson.file, 0, "scene", e.what());
    }
}

LessonRun runLesson(const Lesson& lesson) {
    LessonRun run;
    run.scene = std::make_unique<std::variant<Scene, Scene2D>>(loadLessonScene(lesson));
    AnyStructure built = buildStructure(*run.scene, lesson.accel, {}, lesson.options);
    run.accel2D = std::move(built.in2D);
    run.accel3D = std::move(built.in3D);
    run.log = recordLessonTrace(lesson, *run.scene, run.accel3D ? &*run.accel3D : nullptr,
                                run.accel2D ? &*run.accel2D : nullptr);
    const std::vector<LessonSetup> setups = lesson.setups();
    for (std::size_t i = 1; i < setups.size(); ++i) {
        LessonStructureRun& o = run.others.emplace_back();
        o.setup = setups[i];
        AnyStructure b = buildStructure(*run.scene, o.setup.accel, {}, o.setup.options);
        o.accel2D = std::move(b.in2D);
        o.accel3D = std::move(b.in3D);
        o.log = recordLessonTrace(lesson, o.setup, *run.scene, o.accel3D ? &*o.accel3D : nullptr,
                                  o.accel2D ? &*o.accel2D : nullptr);
    }
    return run;
}

namespace {
/// Cells as the lesson's text writes them, the first `shown` of them.
std::string cellsText(const std::vector<IVecN<2>>& cells, std::size_t shown) {
    std::string s;
    for (std::size_t k = 0; k < std::min(cells.size(), shown); ++k) {
        // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on " " + string here.
        if (k) s += ' ';
        s += cellText({cells[k].x, cells[k].y, 0}, 2);
    }
    return s + (cells.size() > shown ? " ..." : "");
}

/// The slides' loop beside the exact walk, for `ray` through `grid`, in both languages.
LocalText textbookNote(const GridSpec<2, double>& grid, const Ray2& ray) {
    std::vector<IVecN<2>> loop, exact;
    for (const auto& c : ddaTextbook(grid, ray.origin, ray.dir)) loop.push_back(c.cell);
    Dda<2> walk(grid, ray.origin, ray.dir);
    for (bool in = walk.valid(); in; in = walk.next()) exact.push_back(walk.cell());
    std::size_t part = 0;  // the first cell where the two walks differ
    while (part < loop.size() && part < exact.size() && loop[part] == exact[part]) ++part;
    const std::size_t shown = std::max<std::size_t>(6, part + 2);
    const std::string l = cellsText(loop, shown), e = cellsText(exact, shown);
    const auto in = [&](Language lang) {
        std::string text = trf(lang,
                               "The slides' loop (`tMax += tDelta`; X when tMaxX < tMaxY, else Y) "
                               "walks this ray through %1; the exact walk through %2.",
                               {l, e});
        if (part == loop.size() && part == exact.size())
            return text + " " + trf(lang, "Both visit the same %1 cells.", {std::to_string(part)});
        const auto at = [&](const std::vector<IVecN<2>>& cells) {
            return part < cells.size() ? cellText({cells[part].x, cells[part].y, 0}, 2)
                                       : tr(lang, "no cell");
        };
        return text + " " +
               trf(lang, "They part at cell %1: the loop enters %2, the exact walk %3.",
                   {std::to_string(part + 1), at(loop), at(exact)});
    };
    LocalText note;
    for (const Language lang : languages()) note.set(lang, in(lang));
    return note;
}
}  // namespace

void addStepNotes(Lesson& lesson, const std::variant<Scene, Scene2D>& scene,
                  const Accelerator2D* accel2D) {
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        LessonStep& step = lesson.steps[i];
        if (!step.textbookDda) continue;
        const auto* s2 = std::get_if<Scene2D>(&scene);
        // The grid's spec from its outline (app/ asks no structure its type).
        const auto grid = accel2D ? outline(*accel2D).grid : std::nullopt;
        const LessonTrace& t = lesson.trace;
        const bool hasRay = t.kind == LessonTrace::Kind::Ray2D ||
                            (t.kind == LessonTrace::Kind::ExampleRay && s2 && s2->exampleRay);
        if (!s2 || !grid || !hasRay)
            throw LessonError(lesson.file, step.line,
                              "steps[" + std::to_string(i) + "].textbook_dda",
                              "needs a 2D scene, a grid (setup.accel) and a 2D ray (trace)");
        step.note =
            textbookNote(grid->spec, t.kind == LessonTrace::Kind::Ray2D ? t.ray : *s2->exampleRay);
    }
}

std::optional<std::size_t> resolvePosition(const ReplayPosition& at, const EventLog& log) {
    const auto& ev = log.events();
    switch (at.mode) {
        case ReplayPosition::Mode::Start:
            return 0;
        case ReplayPosition::Mode::End:
            return ev.size();
        case ReplayPosition::Mode::Cursor:
            if (at.cursor > ev.size()) return std::nullopt;
            return at.cursor;
        case ReplayPosition::Mode::AfterEvent:
        case ReplayPosition::Mode::BeforeEvent: {
            int seen = 0;
            for (std::size_t i = 0; i < ev.size(); ++i)
                if (ev[i].index() == at.eventKind && ++seen == at.nth)
                    return at.mode == ReplayPosition::Mode::AfterEvent ? i + 1 : i;
            return std::nullopt;
        }
    }
    return std::nullopt;
}

std::string describePosition(const ReplayPosition& at, Language lang) {
    switch (at.mode) {
        case ReplayPosition::Mode::Start:
            return tr(lang, "the start");
        case ReplayPosition::Mode::End:
            return tr(lang, "the end");
        case ReplayPosition::Mode::Cursor:
            return trf(lang, "event %1", {std::to_string(at.cursor)});
        case ReplayPosition::Mode::AfterEvent:
            return feedback::afterEvent(lang, at.eventKind, ordinal(lang, at.nth));
        case ReplayPosition::Mode::BeforeEvent:
            return feedback::beforeEvent(lang, at.eventKind, ordinal(lang, at.nth));
    }
    return "?";
}

namespace {
std::string lowerAscii(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
}
}  // namespace

bool eventMatchesFilter(const Event& e, std::string_view shownLine, std::string_view filter) {
    if (filter.empty()) return true;
    const std::string f = lowerAscii(filter);
    // The event list filters case-insensitively (QSortFilterProxyModel), so does this.
    return lowerAscii(kEventNames[e.index()]).find(f) != std::string::npos ||
           lowerAscii(shownLine).find(f) != std::string::npos;
}

bool eventMatchesFilter(const Event& e, int dims, std::string_view filter) {
    return eventMatchesFilter(e, eventText(e, dims), filter);
}

}  // namespace raystep

// Running a lesson: load its scene, build its structure, record its trace; and finding the
// replay positions its steps and exercises name in that trace.
#include "course/lesson_trace.h"

#include "raystep/render/tracer.h"
#include "raystep/scene/resources.h"
#include "raystep/scene/scene_loader.h"

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

std::unique_ptr<EventLog> recordLessonTrace(const Lesson& lesson,
                                            const std::variant<Scene, Scene2D>& scene,
                                            const Accelerator* accel3D,
                                            const Accelerator2D* accel2D) {
    auto log = std::make_unique<EventLog>();
    const LessonTrace& t = lesson.trace;
    const auto* s2 = std::get_if<Scene2D>(&scene);
    const auto* s3 = std::get_if<Scene>(&scene);
    const auto fail = [&](const std::string& message) {
        throw LessonError(lesson.file, 0, "trace", message);
    };
    switch (t.kind) {
        case LessonTrace::Kind::Build:
            buildStructure(scene, lesson.accel, {}, lesson.options, log.get());
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
    }
    return log;
}

LessonRun runLesson(const Lesson& lesson) {
    LessonRun run;
    try {
        run.scene =
            std::make_unique<std::variant<Scene, Scene2D>>(loadAnyScene(lessonScenePath(lesson)));
    } catch (const SceneError& e) {
        throw LessonError(lesson.file, 0, "scene", e.what());
    }
    AnyStructure built = buildStructure(*run.scene, lesson.accel, {}, lesson.options);
    run.accel2D = std::move(built.in2D);
    run.accel3D = std::move(built.in3D);
    run.log = recordLessonTrace(lesson, *run.scene, run.accel3D ? &*run.accel3D : nullptr,
                                run.accel2D ? &*run.accel2D : nullptr);
    return run;
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
    const bool it = lang == Language::It;
    switch (at.mode) {
        case ReplayPosition::Mode::Start:
            return it ? "l'inizio" : "the start";
        case ReplayPosition::Mode::End:
            return it ? "la fine" : "the end";
        case ReplayPosition::Mode::Cursor:
            return (it ? "l'evento " : "event ") + std::to_string(at.cursor);
        case ReplayPosition::Mode::AfterEvent:
        case ReplayPosition::Mode::BeforeEvent: {
            const bool after = at.mode == ReplayPosition::Mode::AfterEvent;
            return std::string(after ? (it ? "dopo" : "after") : (it ? "prima di" : "before")) +
                   " " + std::string(kEventNames[at.eventKind]) + (it ? " numero " : " number ") +
                   std::to_string(at.nth);
        }
    }
    return "?";
}

}  // namespace raystep

#pragma once
// Running a lesson: its scene, the structure and the trace it records; and the replay positions
// its steps and exercises name, found in that trace.
#include "course/lesson.h"

#include "raystep/accel/accel.h"
#include "raystep/scene/scene.h"
#include "raystep/scene/scene2d.h"
#include "raystep/trace/events.h"

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>

namespace raystep {

/// The traces a lesson's steps and exercises are read from: the lesson's trace through its own
/// structure, and the same trace (the same ray, pixel or build) through each other structure a
/// step or an exercise sets up, by LessonSetup::key().
struct LessonLogs {
    /// One trace for every step and exercise (a lesson of one structure, or a test's log).
    LessonLogs(const EventLog& own) : own(&own) {}  // NOLINT: implicit on purpose
    const EventLog* own;
    std::map<std::string, const EventLog*> bySetup;
    /// The trace through `setup` (a step's or an exercise's own); the lesson's for none.
    const EventLog& of(const std::optional<LessonSetup>& setup) const {
        if (setup)
            if (const auto it = bySetup.find(setup->key()); it != bySetup.end()) return *it->second;
        return *own;
    }
};

/// One structure built over the lesson's scene, and the lesson's trace through it.
struct LessonStructureRun {
    LessonSetup setup;
    std::optional<Accelerator> accel3D;
    std::optional<Accelerator2D> accel2D;
    std::unique_ptr<EventLog> log;
};

/// A lesson made ready: its scene, the structure and the recorded trace; and the same trace
/// through every other structure its steps and exercises set up.
struct LessonRun {
    std::unique_ptr<std::variant<Scene, Scene2D>> scene;
    std::optional<Accelerator> accel3D;
    std::optional<Accelerator2D> accel2D;
    std::unique_ptr<EventLog> log;
    std::vector<LessonStructureRun> others;  // Lesson::setups() after the lesson's own
    LessonLogs logs() const;
};
/// The lesson's scene, as a path the app and loadAnyScene accept (not for an inline scene).
std::string lessonScenePath(const Lesson& lesson);
/// The lesson's scene, a file's or its inline one; LessonError naming the lesson otherwise.
std::variant<Scene, Scene2D> loadLessonScene(const Lesson& lesson);
/// Loads the scene, builds the structure and records the trace.
LessonRun runLesson(const Lesson& lesson);
/// Records the lesson's trace with a scene and structure already made (the lesson's own).
std::unique_ptr<EventLog> recordLessonTrace(const Lesson& lesson,
                                            const std::variant<Scene, Scene2D>& scene,
                                            const Accelerator* accel3D,
                                            const Accelerator2D* accel2D);
/// The same through the structure `setup` (built over `scene` with it). A lesson with an
/// overlap exercise also records the tree's node boxes (EventLog::nodes), whose answer they are.
std::unique_ptr<EventLog> recordLessonTrace(const Lesson& lesson, const LessonSetup& setup,
                                            const std::variant<Scene, Scene2D>& scene,
                                            const Accelerator* accel3D,
                                            const Accelerator2D* accel2D);

/// Fills the notes of the steps that ask for one ("textbook_dda": the slides' DDA loop beside the
/// exact walk for the lesson's 2D ray), from the lesson's scene and structure. Throws a
/// LessonError naming the step when the lesson is not a 2D ray through a grid.
void addStepNotes(Lesson& lesson, const std::variant<Scene, Scene2D>& scene,
                  const Accelerator2D* accel2D);

/// The cursor a position stands for in `log`; nullopt when the log has no such event.
std::optional<std::size_t> resolvePosition(const ReplayPosition& at, const EventLog& log);
std::string describePosition(const ReplayPosition& at, Language lang = Language::En);

/// True when a step's event filter shows `e`: `filter` (case aside) is part of the event's kind
/// name ("dda_cell", "ray_begin") or of its line in the event list. An empty filter shows all.
bool eventMatchesFilter(const Event& e, int dims, std::string_view filter);
/// The same with the line the caller shows for `e` (the app's event list, in its language).
bool eventMatchesFilter(const Event& e, std::string_view shownLine, std::string_view filter);

}  // namespace raystep

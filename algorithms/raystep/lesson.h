#pragma once
// Lessons (docs/lesson-format.md): the lecture's topics as text in English and Italian, a scene,
// the structure to build, the trace to record, steps that put the replay somewhere, and exercises
// whose right answer is read from the recorded trace, never written in the lesson file.
// The app shows them; `raystep-cli lesson` lists, validates and grades them.
#include "raystep/accel/accel.h"
#include "raystep/trace/events.h"
#include "raystep/base/file_error.h"
#include "raystep/scene/scene.h"
#include "raystep/scene/scene2d.h"

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace raystep {

enum class Language { En, It };
std::optional<Language> parseLanguage(std::string_view code);  // "en", "it"

/// A text in both languages (Italian falls back to English where a lesson leaves it out).
struct LocalText {
    std::string en, it;
    const std::string& in(Language l) const { return l == Language::It && !it.empty() ? it : en; }
};

/// A lesson, answers or progress file that cannot be used: file, line, key and why.
class LessonError : public FileError {
  public:
    using FileError::FileError;
};

/// Where a step or an exercise puts the replay cursor. Positions name events, not counts, so a
/// lesson survives a change in how many events come before.
struct ReplayPosition {
    enum class Mode { Start, End, Cursor, AfterEvent, BeforeEvent };
    Mode mode = Mode::Start;
    std::size_t cursor = 0;     // Cursor: this many events applied
    std::size_t eventKind = 0;  // AfterEvent / BeforeEvent: variant index of the event
    int nth = 1;                // ... its nth occurrence (1-based)
};

enum class LessonView { View2D, View3D, Image };

/// The 3D view's camera for a step: degrees around the scene's centre, and a zoom factor.
struct LessonCamera {
    double azimuth = 0.0, elevation = 0.0, zoom = 1.0;
};

struct LessonStep {
    LocalText text;
    ReplayPosition at;
    std::string filter;  // what the event list shows (its filter text), empty = everything
    std::optional<LessonCamera> camera;
    int line = 0;  // in the lesson file, for messages
};

/// The recording a lesson is about.
struct LessonTrace {
    enum class Kind { ExampleRay, Ray2D, Pixel, Build };
    Kind kind = Kind::ExampleRay;
    Ray2 ray;          // Ray2D
    int x = 0, y = 0;  // Pixel, in a width x height image
    int width = 320, height = 240;
};

/// A sweep of the grid's resolution (the lesson on voxel size): the same rays at each resolution.
struct GridSweepSpec {
    std::vector<int> resolutions;  // cells per axis
    int width = 64, height = 48;   // the camera's primary rays (3D); 2D: a fan of rays
};

enum class ExerciseKind { NextCell, Value, PickSplit, Count, HitOrMiss };
std::string_view exerciseKindName(ExerciseKind k);

/// Quantities a Value exercise asks for; each is read from the next event of its kind at or after
/// the exercise's position.
enum class Quantity {
    TMaxX,
    TMaxY,
    TMaxZ,  // next dda_cell
    TDeltaX,
    TDeltaY,
    TDeltaZ,  // next dda_setup
    TEnter,
    TExit,  // next dda_setup
    HitT,
    HitU,
    HitV,   // next ray_hit (u, v: barycentric coordinates on a triangle)
    TestT,  // next primitive_test that hits
    NodeTNear,
    NodeTFar,  // next node_enter
    CandidatePL,
    CandidatePR,
    CandidateCost,  // next split_candidate
};
std::optional<Quantity> parseQuantity(std::string_view name);
std::string_view quantityName(Quantity q);

struct Exercise {
    std::string id;
    ExerciseKind kind = ExerciseKind::Value;
    LocalText prompt, hint;
    ReplayPosition at;
    Quantity quantity = Quantity::TMaxX;  // Value
    std::size_t countKind = 0;            // Count: variant index of the events counted
    std::optional<RayKind> rayKind;       // Count of ray_begin: only rays of this kind
    std::optional<int> rayDepth;          // ... and of this depth (0 = primary)
    std::optional<ReplayPosition> until;  // Count: up to here (else to the end)
    bool withT = false;                   // HitOrMiss: the t of a hit is asked too
    double tolerance = 0.01;              // relative (absolute below 1) for numbers
    int line = 0;
};

struct Lesson {
    std::string id;
    int number = 0;
    LocalText title, text;
    std::string scene;  // a built-in scene name or a path relative to the lesson file
    AccelKind accel = AccelKind::BruteForce;
    AccelOptions options;
    std::vector<LessonView> views;
    LessonTrace trace;
    std::optional<GridSweepSpec> sweep;
    std::vector<LessonStep> steps;
    std::vector<Exercise> exercises;
    std::string file;      // where it was read from (messages)
    bool builtin = false;  // embedded in raystep (its scene is a built-in name)

    const Exercise* exercise(std::string_view exerciseId) const;
};

/// Parses lesson text; errors name `fileName`, the line and the key.
Lesson loadLessonText(std::string_view text, const std::string& fileName);
/// A built-in lesson by id ("grid-2d-dda") or number ("6"), else a lesson file.
Lesson loadLesson(const std::string& idOrPath);
/// The built-in lessons in the lecture's order.
std::vector<Lesson> builtinLessons();

/// A lesson made ready: its scene, the structure and the recorded trace.
struct LessonRun {
    std::unique_ptr<std::variant<Scene, Scene2D>> scene;
    std::optional<Accelerator> accel3D;
    std::optional<Accelerator2D> accel2D;
    std::unique_ptr<EventLog> log;
};
/// The lesson's scene, as a path the app and loadAnyScene accept.
std::string lessonScenePath(const Lesson& lesson);
/// Loads the scene, builds the structure and records the trace.
LessonRun runLesson(const Lesson& lesson);
/// Records the lesson's trace with a scene and structure already made.
std::unique_ptr<EventLog> recordLessonTrace(const Lesson& lesson,
                                            const std::variant<Scene, Scene2D>& scene,
                                            const Accelerator* accel3D,
                                            const Accelerator2D* accel2D);

/// The cursor a position stands for in `log`; nullopt when the log has no such event.
std::optional<std::size_t> resolvePosition(const ReplayPosition& at, const EventLog& log);
std::string describePosition(const ReplayPosition& at, Language lang = Language::En);

/// A student's answer. NextCell: the cell's indices; Value and Count: one number; PickSplit:
/// axis (0, 1, 2) and position; HitOrMiss: hit, and t when asked.
struct Answer {
    std::vector<double> numbers;
    std::optional<bool> hit;
};
/// Reads an answer as typed: "2,1" (cell), "0.75" (value, count), "x=2.5" (split),
/// "miss" or "hit 3.55" (hit or miss). nullopt with `why` set when it is not such an answer.
std::optional<Answer> parseAnswer(const Exercise& ex, std::string_view text, std::string* why);
std::string formatAnswer(const Exercise& ex, const Answer& a);

/// The candidates of the split a PickSplit exercise is about (those the app lists).
std::vector<SplitCandidate> splitCandidates(const Exercise& ex, const EventLog& log);

/// The right answer, read from the trace; throws LessonError (naming the exercise's line in
/// `lessonFile`) when the trace does not hold what the exercise asks about.
Answer referenceAnswer(const Exercise& ex, const EventLog& log, const std::string& lessonFile);

struct Verdict {
    bool correct = false;
    std::string expected;  // the reference answer, as text
    std::string feedback;  // why the right answer is right, from the trace
};
Verdict checkAnswer(const Exercise& ex, const EventLog& log, const Answer& answer, Language lang,
                    const std::string& lessonFile);

/// Checks what `raystep-cli lesson validate` checks: the scene loads, the trace records, every
/// step's and exercise's position exists in it and every exercise has a reference answer.
/// Throws LessonError on the first problem.
void validateLesson(const Lesson& lesson);

/// A course's answers file: {"lesson": ID, "answers": {exercise id: answer}} where an answer is a
/// number, an array of numbers (a cell), a string as typed in the app, or true/false (hit/miss).
struct AnswerSheet {
    std::string lesson;  // the id, or the number as text
    int lessonLine = 0;
    std::map<std::string, std::string> answers;  // as text, for parseAnswer
    std::map<std::string, int> lines;
};
AnswerSheet loadAnswerSheet(std::string_view text, const std::string& fileName);
/// Reads the answers file at `path` (a regular file of at most 8 MB) and parses it.
AnswerSheet loadAnswerSheetFile(const std::string& path);

/// Grades a sheet: per exercise, correct or not and why; the score is the number right.
struct Grade {
    struct Item {
        std::string exercise;
        bool answered = false, correct = false;
        std::string given, expected, feedback;
    };
    std::vector<Item> items;
    int score = 0;
};
Grade gradeAnswers(const Lesson& lesson, const EventLog& log, const AnswerSheet& sheet,
                   Language lang, const std::string& sheetFile);

/// A student's progress, saved by the app under the user's data folder.
struct LessonProgress {
    struct ExerciseRecord {
        bool correct = false;
        int attempts = 0;
        std::string answer;
    };
    int step = 0;
    std::map<std::string, ExerciseRecord> exercises;
};
struct Progress {
    std::map<std::string, LessonProgress> lessons;  // by lesson id
};
Progress parseProgress(std::string_view text, const std::string& fileName);
/// Reads the progress file at `path`: nullopt when there is none yet; LessonError when it cannot
/// be read (a folder, a special file, over 8 MB) or parsed.
std::optional<Progress> loadProgressFile(const std::string& path);
std::string progressToJson(const Progress& p);
/// Folds progress saved by another run (another window of the app, open at the same time) into
/// `into`, so that saving `into` loses neither's answers: an exercise right in either is right,
/// its attempts are the larger count (with that run's answer), lessons and exercises only one
/// knows are kept, and `into`'s own steps win. Records already in `into` do not move.
void mergeProgress(Progress& into, const Progress& saved);
/// A report for a course: per lesson, exercises done, right, attempts (Markdown).
std::string progressReport(const Progress& p, const std::vector<Lesson>& lessons, Language lang);

/// One resolution of a grid sweep: what the structure cost and what the rays paid.
struct GridSweepRow {
    int resolution = 0;
    std::uint64_t cells = 0, references = 0;
    double buildMs = 0.0, traceMs = 0.0;
    double testsPerRay = 0.0, cellsPerRay = 0.0, skipsPerRay = 0.0;
};
/// Runs the sweep (3D: the camera's primary rays; 2D: a fan of rays from the example ray's
/// origin). `progress` may cancel (BuildCancelled).
std::vector<GridSweepRow> runGridSweep(const std::variant<Scene, Scene2D>& scene,
                                       const GridSweepSpec& spec, const ProgressFn& progress = {});

}  // namespace raystep

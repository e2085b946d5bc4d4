#pragma once
// Lessons (docs/lesson-format.md): the model and its loader. A lesson is the lecture's topic as
// text in English and Italian, a scene, the structure to build, the trace to record, steps that
// put the replay somewhere, and exercises whose right answer is read from the recorded trace,
// never written in the lesson file (course/exercise.h). The app shows them; `raystep-cli lesson`
// lists, validates and grades them.
#include "course/grid_sweep.h"

#include "raystep/accel/accel.h"
#include "raystep/base/file_error.h"
#include "raystep/base/i18n.h"
#include "raystep/scene/scene2d.h"
#include "raystep/trace/events.h"

#include <array>
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// A text in every language a lesson gives it in, by language code ("en", "it", any code of the
/// registry, base/i18n.h); a language the lesson leaves out reads the English.
struct LocalText {
    std::string en;                                         // the source text, required
    std::map<std::string, std::string, std::less<>> other;  // every other language: code -> text

    /// The text in `l`, else the English.
    const std::string& in(Language l) const;
    /// Whether the lesson gives a text of its own in `l` (English always).
    bool has(Language l) const { return l == Language::En || !slot(l).empty(); }
    void set(Language l, std::string text);

  private:
    const std::string& slot(Language l) const;
};

/// A slip in the slides, pointed out: the slide's line as written, the right one, and why. The
/// app shows it as a marked box, "Note on the slides" (erratumHeading), under the lesson's or
/// the step's text.
struct Erratum {
    LocalText slide, correct, why;
    int line = 0;
};
/// "Note on the slides" in `lang`: the heading of an erratum's box.
std::string erratumHeading(Language lang);

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

// Board: the board table dock (the slides' DDA table), beside a 2D or a 3D scene.
enum class LessonView { View2D, View3D, Image, Board };
std::string_view lessonViewName(LessonView v);  // "2d", "3d", "image", "board"

/// The 3D view's camera for a step: degrees around the scene's centre, and a zoom factor.
struct LessonCamera {
    double azimuth = 0.0, elevation = 0.0, zoom = 1.0;
};

/// The structure a lesson, a step or an exercise is about: its kind and its build options (the
/// keys of `setup`, docs/lesson-format.md).
struct LessonSetup {
    AccelKind accel = AccelKind::BruteForce;
    AccelOptions options;
    /// A spot_bug exercise's id: the trace through this setup is that exercise's wrong walk,
    /// replayed on the structure's grid, instead of the lesson's trace (empty: the lesson's).
    std::string replay = {};  // initialised: {accel, options} stays a whole initialiser
    /// Two setups with the same key build the same structure: the kind and every option its
    /// build reads, so a step and an exercise naming the same BVH share one trace.
    std::string key() const;
    /// "bvh SAH", "grid": as render --stats and compare name it.
    std::string name() const;
};

struct LessonStep {
    LocalText text;
    // Its own structure (the lesson's setup with the step's keys over it), else the lesson's.
    std::optional<LessonSetup> setup;
    // "compare": the structures the step offers to compare on its ray (empty: no button).
    std::vector<StructureChoice> compare;
    ReplayPosition at;
    std::string filter;  // what the event list shows (its filter text), empty = everything
    std::optional<LessonCamera> camera;
    // "textbook_dda": the step sets the slides' own DDA loop (ddaTextbook) beside the exact walk
    // for the lesson's 2D ray; `note` holds that comparison once the lesson has run (addStepNotes).
    bool textbookDda = false;
    LocalText note;
    std::vector<Erratum> errata;
    int line = 0;  // in the lesson file, for messages
};

/// The recording a lesson is about.
struct LessonTrace {
    enum class Kind { ExampleRay, Ray2D, Pixel, Build, Ray3D };
    Kind kind = Kind::ExampleRay;
    Ray2 ray;          // Ray2D
    Ray ray3D;         // Ray3D: one ray through a 3D scene's structure (a practice's DDA walk)
    int x = 0, y = 0;  // Pixel, in a width x height image
    int width = 320, height = 240;
};

enum class ExerciseKind {
    NextCell,
    Value,
    PickSplit,
    Count,
    HitOrMiss,
    Choice,     // a conceptual question: the answer is in the lesson file (the one exception)
    Sequence,   // the cells the DDA visits, or the nodes TestTree enters, in order
    SweepPick,  // the sweep's resolution of the lowest metric
    Compute,    // a hand computation from data the prompt gives
    Overlap,    // two boxes of the tree that share space, neither inside the other (a BVH)
    SpotBug,    // the first wrong step of a replayed DDA walk with a classic mistake in it
};
/// How many kinds there are: a new kind goes last, and moves this.
constexpr int kExerciseKindCount = static_cast<int>(ExerciseKind::SpotBug) + 1;
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

/// One option of a Choice exercise, and why it is right or wrong.
struct ChoiceOption {
    LocalText text, why;
};

/// The data of a Compute exercise: a ray and one shape (or a kd node and a plane for the SAH).
struct ComputeGiven {
    enum class Shape { Sphere, Triangle, Plane, Box, Grid, Node, Shading };
    Shape shape = Shape::Sphere;
    int dims = 3;                    // Grid and Node: 2 or 3, by the vectors' length
    std::array<double, 3> o{}, d{};  // the ray (all but Node)
    std::array<double, 3> center{};  // Sphere: centre and radius
    double radius = 0.0;
    std::array<std::array<double, 3>, 3> tri{};  // Triangle: a, b, c
    std::array<double, 3> normal{};              // Plane: the points p with p.n = k
    double k = 0.0;
    std::array<double, 3> lo{}, hi{};  // Box, Node: min and max; Grid: min and cell size
    std::array<int, 3> res{0, 0, 0};   // Grid: cells per axis (0: 1024)
    int axis = 0;                      // Node: the plane's axis and position
    double at = 0.0;
    int nl = 0, nr = 0;  // Node: primitives left and right
    // Node's SAH and SweepPick's cost: the lesson's setup (c_trav, c_isect, empty_bonus).
    double cTrav = 1.0, cIsect = 5.0, emptyBonus = 0.5;
    // Shading: Phong at a point, with `normal` as n; the light's and the eye's unit directions,
    // the material's kd, ks and shininess, the light's intensity (one grey value).
    std::array<double, 3> toLight{}, toViewer{};
    double kd = 0.0, ks = 0.0, shininess = 1.0, intensity = 1.0;
    bool specular = false;        // v, ks and shininess given: r.v and the specular term defined
    std::vector<double> numbers;  // every number given, as written, for the prompt check
};

enum class SweepMetric { Cost, TestsPerRay, CellsPerRay };

/// A spot_bug exercise's ray: 2D or 3D by its length in the lesson file.
struct WalkRay {
    std::array<double, 3> o{}, d{};
    int dims = 2;
};
std::string_view sweepMetricName(SweepMetric m);

struct Exercise {
    std::string id;
    ExerciseKind kind = ExerciseKind::Value;
    LocalText prompt;
    // Revealed one at a time: a nudge, then the formula, then the worked first step.
    std::vector<LocalText> hints;
    ReplayPosition at;
    Quantity quantity = Quantity::TMaxX;     // Value
    std::size_t countKind = 0;               // Count: variant index of the events counted
    std::optional<RayKind> rayKind;          // Count of ray_begin: only rays of this kind
    std::optional<int> rayDepth;             // ... and of this depth (0 = primary)
    std::optional<ReplayPosition> until;     // Count, Sequence: up to here (else to the end)
    bool withT = false;                      // HitOrMiss: the t of a hit is asked too
    double tolerance = 0.01;                 // relative (absolute below 1) for numbers
    std::vector<ChoiceOption> choices;       // Choice: 2 to 6 options
    int answer = 0;                          // Choice: the right option (0-based)
    bool ofNodes = false;                    // Sequence: node_enter ids (else dda_cell cells)
    std::optional<int> length;               // Sequence: only the first N
    SweepMetric metric = SweepMetric::Cost;  // SweepPick
    ComputeGiven given;                      // Compute
    std::string computeQuantity;             // Compute: "t0", "tMax.x", "sahCost", ...
    std::string mistake;                     // SpotBug: a DDA mistake's name (assess/mistakes.h)
    std::optional<WalkRay> walkRay;          // SpotBug: its ray (else the lesson's first ray)
    // Its own structure: the answer is read from the lesson's trace through it (the same ray).
    std::optional<LessonSetup> setup;
    int line = 0;
};

struct Lesson {
    std::string id;
    int number = 0;
    LocalText title, text;
    std::string scene;  // a built-in scene name or a path relative to the lesson file
    // An inline scene ("scene": {...}, a generated practice's): its JSON text; `scene` then
    // names the lesson file's key for messages.
    std::string sceneText;
    AccelKind accel = AccelKind::BruteForce;
    AccelOptions options;
    std::vector<LessonView> views;
    LessonTrace trace;
    std::optional<GridSweepSpec> sweep;
    std::vector<LessonStep> steps;
    std::vector<Exercise> exercises;
    std::vector<Erratum> errata;  // the lesson's own, shown under its text
    std::string file;             // where it was read from (messages)
    bool builtin = false;         // embedded in raystep (its scene is a built-in name)

    const Exercise* exercise(std::string_view exerciseId) const;
    /// The lesson's own structure (`setup`).
    LessonSetup setup() const { return {accel, options}; }
    /// The structure a step or an exercise is about: its own setup, else the lesson's.
    LessonSetup setupOf(const std::optional<LessonSetup>& own) const {
        return own ? *own : setup();
    }
    /// Every structure the lesson's steps and exercises are about, the lesson's first, each once.
    std::vector<LessonSetup> setups() const;
};

/// Parses lesson text; errors name `fileName`, the line and the key.
Lesson loadLessonText(std::string_view text, const std::string& fileName);
/// A built-in lesson by id ("grid-2d-dda") or number ("6"), else a lesson file.
Lesson loadLesson(const std::string& idOrPath);
/// "6. The 2D DDA" as a lesson's heading and the window name it; a practice instance, whose
/// number only orders it after the lecture's, is its title alone.
std::string lessonHeading(const Lesson& lesson, Language lang);
/// The built-in lessons in the lecture's order.
std::vector<Lesson> builtinLessons();

}  // namespace raystep

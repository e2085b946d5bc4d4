#pragma once
// Where a text gives an exercise's answer away (`raystep-cli lesson validate`): the answer in the
// forms a text would write it, and the search for them. A number as a text prints it (rounded, or
// close enough that the grader would take it, with either decimal mark), a cell in any of its
// forms ("(3, 1)", "3,1", "X = 3, Y = 1"), a walk's cells in order, TestTree's node order, a
// test's outcome named with its primitive ("misses the circle", "colpisce il triangolo 2"), the
// plane of a split ("y = 2.96"), a sweep's resolution ("8 x 8 x 8").
#include "course/exercise.h"
#include "course/grid_sweep.h"
#include "course/lesson.h"

#include "raystep/trace/events.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// An exercise's answer, in the forms findAnswer looks for.
struct AnswerForms {
    std::vector<double> numbers;  // value, compute, the t of a hit (whole 0 and 1 left out)
    double tolerance = 0.01;      // the exercise's: a number the grader takes is the answer
    std::vector<std::array<int, 3>> cells;  // next_cell: one; a sequence: its cells in order
    int dims = 2;
    std::vector<int> nodes;                     // a sequence of the nodes TestTree enters, in order
    std::vector<std::array<int, 2>> nodePairs;  // overlap: every right pair
    struct Outcome {
        std::uint32_t prim = 0;
        bool hit = false;
        bool circle = false, segment = false, sphere = false, triangle = false;  // its kind
        bool onlyOfItsKind = false;      // "the circle" can mean no other primitive of the scene
        std::vector<std::string> names;  // its material's name when no other has it ("mirror")
    };
    std::optional<Outcome> outcome;  // hit_or_miss: the test's verdict on this primitive
    struct Plane {
        int axis = 0;
        double position = 0.0;
    };
    std::optional<Plane> plane;     // pick_split
    std::optional<int> resolution;  // sweep_pick: cells per axis
    /// The answer as validate's message shows it ("(3, 1)", "hit on primitive 2").
    std::string describe;
};

/// The forms of `ex`'s reference answer in the lesson's trace (the scene, when given, names a
/// tested primitive's kind). A choice and a count have none: a choice's options are on screen
/// by design, and a count is one small whole number among many in every text.
AnswerForms answerForms(const Exercise& ex, const EventLog& log, const std::string& lessonFile,
                        const LessonScene* scene, const std::vector<GridSweepRow>* sweep);

/// Where `text` writes the answer: the words as written, or nullopt. A yes-or-no question that
/// names a test ("Does the ray hit triangle 2?") asks it, and does not count. How a primitive is
/// named depends on the text: an exercise's prompt, hint or option is about the exercise's
/// primitive, so "the circle" names it; the lesson's and the steps' prose talk of primitives in
/// general, so only its number ("triangle 2"), its own name ("the mirror") or a kind it alone has
/// name it; a compute exercise's texts are about the data they give, so only the number does.
enum class TextRole { Prose, Exercise, GivenData };
std::optional<std::string> findAnswer(const AnswerForms& forms, std::string_view text,
                                      TextRole role = TextRole::Prose);

}  // namespace raystep

// Lesson files: loadLessonText on the input, then validateLesson on what it accepted (the scene is
// loaded, the structure built, the trace recorded, every position and answer looked up).
// The lesson "lives" in a folder that does not exist, so a relative scene path finds no file;
// a built-in scene name works as in a real lesson.
#include "course/grading.h"
#include "course/lesson.h"
#include "fuzz_support.h"

namespace {

// Under the sanitizers, building the stadium (51,200 triangles) or a grid of up to 512^3 cells
// takes longer than the 10 s timeout: that is the builders' speed (performance.md), not the
// reader's, so such lessons are read but not validated.
bool quickToValidate(const raystep::Lesson& l) {
    if (l.scene == "stadium") return false;
    // A sweep_pick exercise runs the lesson's sweep (up to 256^3 cells per grid) to validate.
    for (const raystep::Exercise& e : l.exercises)
        if (e.kind == raystep::ExerciseKind::SweepPick) return false;
    const raystep::GridOptions& g = l.options.grid;
    if (g.res && static_cast<long>((*g.res)[0]) * (*g.res)[1] * (*g.res)[2] > 64 * 64 * 64)
        return false;
    return g.lambda <= 1000.0;  // the built-in scenes other than the stadium: under 100 primitives
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text = raystep::fuzz::asText(data, size);
    raystep::fuzz::expectOwnErrorOnly<raystep::LessonError>("loadLessonText + validateLesson", [&] {
        const raystep::Lesson lesson =
            raystep::loadLessonText(text, "/nonexistent-raystep-fuzz/lesson.json");
        if (quickToValidate(lesson)) raystep::validateLesson(lesson);
    });
    return 0;
}

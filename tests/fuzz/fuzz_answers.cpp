// Answer sheets: loadAnswerSheet on the input; a sheet that loads and names a built-in lesson is
// then graded against that lesson's trace (parseAnswer reads every answer as typed text).
#include "course/grading.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"
#include "fuzz_support.h"

#include <map>

namespace {

struct Recorded {
    raystep::Lesson lesson;
    raystep::LessonRun run;
};

// Recording a lesson's trace is slow next to reading a sheet: once per lesson, on first use.
const Recorded* builtinLessonRun(const std::string& idOrNumber) {
    static std::map<std::string, std::unique_ptr<Recorded>> runs;
    static const std::vector<raystep::Lesson> lessons = raystep::builtinLessons();
    for (const raystep::Lesson& l : lessons) {
        if (l.id != idOrNumber && std::to_string(l.number) != idOrNumber) continue;
        auto& slot = runs[l.id];
        if (!slot) slot.reset(new Recorded{l, raystep::runLesson(l)});
        return slot.get();
    }
    return nullptr;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text = raystep::fuzz::asText(data, size);
    raystep::fuzz::expectOwnErrorOnly<raystep::LessonError>("loadAnswerSheet + gradeAnswers", [&] {
        const raystep::AnswerSheet sheet = raystep::loadAnswerSheet(text, "fuzz-answers.json");
        if (const Recorded* r = builtinLessonRun(sheet.lesson))
            (void)raystep::gradeAnswers(r->lesson, r->run.logs(), sheet, raystep::Language::En,
                                        "fuzz-answers.json");
    });
    return 0;
}

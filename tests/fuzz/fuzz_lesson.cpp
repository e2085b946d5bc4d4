// Lesson files: loadLessonText on the input, then validateLesson on what it accepted (the scene is
// loaded, the structure built, the trace recorded, every position and answer looked up).
// The lesson "lives" in a folder that does not exist, so a relative scene path finds no file;
// a built-in scene name works as in a real lesson.
#include "fuzz_support.h"
#include "raystep/lesson.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text = raystep::fuzz::asText(data, size);
    raystep::fuzz::expectOwnErrorOnly<raystep::LessonError>("loadLessonText + validateLesson", [&] {
        const raystep::Lesson lesson =
            raystep::loadLessonText(text, "/nonexistent-raystep-fuzz/lesson.json");
        raystep::validateLesson(lesson);
    });
    return 0;
}

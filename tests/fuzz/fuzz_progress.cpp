// Progress files: parseProgress on the input; what it accepts is written back with
// progressToJson (as the app saves it) and must read again to the same progress.
#include "fuzz_support.h"
#include "course/progress.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text = raystep::fuzz::asText(data, size);
    raystep::Progress progress;
    try {
        progress = raystep::parseProgress(text, "fuzz-progress.json");
    } catch (const raystep::LessonError&) {
        return 0;
    } catch (const std::exception& e) {
        raystep::fuzz::finding("parseProgress", "threw " + raystep::fuzz::typeName(typeid(e)) +
                                                    " (not its own error type): " + e.what());
    }
    try {
        const std::string saved = raystep::progressToJson(progress);
        const std::string again =
            raystep::progressToJson(raystep::parseProgress(saved, "fuzz-progress-saved.json"));
        if (again != saved)
            raystep::fuzz::finding("progressToJson", "a saved progress file reads back different");
    } catch (const std::exception& e) {
        raystep::fuzz::finding("progressToJson + parseProgress",
                               "an accepted progress file, saved, does not read back: " +
                                   raystep::fuzz::typeName(typeid(e)) + ": " + e.what());
    }
    return 0;
}

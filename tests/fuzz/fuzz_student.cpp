// A student's trace (assess/): readStudentTrace on the input, in 2D and 3D; what it accepts is
// assessed against a bare walk and against lecture-grid's grid, which must return a verdict for
// every ray (a student's file is anyone's bytes).
#include "fuzz_support.h"
#include "raystep/assess/assess.h"
#include "raystep/scene/scene_loader.h"

#include <optional>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace raystep;
    const std::string_view text = fuzz::asText(data, size);
    static const std::variant<Scene, Scene2D> scene = loadAnyScene("lecture-grid");
    static const AnyStructure grid = buildStructure(scene, AccelKind::Grid, {}, {});
    static const Reference onScene = Reference::structure(grid, AccelKind::Grid);
    for (int dims : {2, 3}) {
        std::optional<StudentTrace> trace;
        try {
            trace.emplace(readStudentTrace(text, "fuzz-student.jsonl", dims));
        } catch (const FileError&) {
            continue;
        } catch (const std::exception& e) {
            fuzz::finding("readStudentTrace", "threw " + fuzz::typeName(typeid(e)) +
                                                  " (not its own error type): " + e.what());
        }
        GridSpec<3, double> g;
        g.lo = {-1, -1, -1};
        g.hi = {3, 2, 1};
        g.res = {4, 3, 2};
        try {
            const Assessment a = assess(*trace, Reference::dda(g, dims), Language::En);
            if (a.rays.size() != trace->rays.size())
                fuzz::finding("assess", "a verdict is missing for a ray");
            (void)assessmentJson(a, Language::It);
            if (dims == 2)
                (void)assessmentText(assess(*trace, onScene, Language::It), Language::It);
        } catch (const std::exception& e) {
            fuzz::finding("assess", "threw on an accepted trace: " + fuzz::typeName(typeid(e)) +
                                        ": " + e.what());
        }
    }
    return 0;
}

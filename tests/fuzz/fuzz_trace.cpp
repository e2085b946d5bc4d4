// Trace files: traceFromJson on the input; what it accepts is written back with traceToJson and
// must read again to the same trace.
#include "fuzz_support.h"
#include "raystep/trace/trace_io.h"

#include <optional>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text = raystep::fuzz::asText(data, size);
    raystep::TraceInfo info;
    std::optional<raystep::EventLog> log;
    try {
        log.emplace(raystep::traceFromJson(text, "fuzz-trace.json", &info));
    } catch (const raystep::TraceError&) {
        return 0;
    } catch (const std::exception& e) {
        raystep::fuzz::finding("traceFromJson", "threw " + raystep::fuzz::typeName(typeid(e)) +
                                                    " (not its own error type): " + e.what());
    }
    try {
        const std::string saved = raystep::traceToJson(*log, info);
        raystep::TraceInfo info2;
        const std::string again = raystep::traceToJson(
            raystep::traceFromJson(saved, "fuzz-trace-saved.json", &info2), info2);
        if (again != saved)
            raystep::fuzz::finding("traceToJson", "a written trace reads back different");
    } catch (const std::exception& e) {
        raystep::fuzz::finding("traceToJson + traceFromJson",
                               "an accepted trace, written, does not read back: " +
                                   raystep::fuzz::typeName(typeid(e)) + ": " + e.what());
    }
    return 0;
}

#pragma once
// The trace file (docs/trace-format.md): an event log as versioned JSON, for the app, the course
// and students' own scripts. Reading checks every field and names the file, line and key of the
// first problem.
#include "raystep/trace/events.h"
#include "raystep/base/file_error.h"

#include <string>
#include <string_view>

namespace raystep {

constexpr int kTraceFormatVersion = 1;

/// What the log is a trace of (free-form except where noted).
struct TraceInfo {
    std::string scene;  // scene name or file
    std::string accel;  // e.g. "kdtree sah"
    std::string what;   // "pixel", "build", "ray"
    int pixelX = -1, pixelY = -1;
    int width = 0, height = 0;
};

/// A trace file that cannot be read: file, line, key and why ("file:line: key 'k': message").
class TraceError : public FileError {
  public:
    using FileError::FileError;
};

/// The whole log as trace-file JSON text.
std::string traceToJson(const EventLog& log, const TraceInfo& info);

/// Parses trace-file text; throws TraceError "file:line: key 'path': message".
EventLog traceFromJson(std::string_view text, const std::string& fileName,
                       TraceInfo* info = nullptr);

}  // namespace raystep

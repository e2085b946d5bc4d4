#pragma once
// Reading a file (a scene, a trace, the course's files) so that every error names the file, the
// line and the key: one function that opens files, the JSON parse behind a depth cap, and typed
// accessors over nlohmann::json that throw the loader's own error type. Internal to the core and
// the course library (app/course).
#include "raystep/base/file_error.h"
#include "raystep/base/json_lines.h"
#include "raystep/base/math.h"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace raystep::detail {

using nlohmann::json;

/// The most a JSON file (a scene, the course's files) may hold: the built-in ones are under
/// 64 KB, and nlohmann's tree of a hostile 8 MB stays within a few hundred MB.
constexpr std::size_t kMaxJsonFileBytes = std::size_t(8) << 20;
/// The most an OBJ mesh may hold (the stadium's knot is 1.6 MB; 256 MB is about 10M triangles).
constexpr std::size_t kMaxObjFileBytes = std::size_t(256) << 20;

/// Why a file could not be read, in words for a message: "no such file", "it is a folder", ...
class ReadFailure : public std::runtime_error {
  public:
    ReadFailure(const std::string& why, bool missing)
        : std::runtime_error(why), missing_(missing) {}
    bool missing() const { return missing_; }  // nothing there (as opposed to unreadable)

  private:
    bool missing_;
};

[[noreturn]] inline void throwReadFailure(int error) {
    switch (error) {
        case ENOENT:
            throw ReadFailure("no such file", true);
        case ENOTDIR:
            throw ReadFailure("no such file (a part of its path is not a folder)", true);
        case EACCES:
            throw ReadFailure("permission denied", false);
        case ELOOP:
            throw ReadFailure("too many levels of symbolic links (a loop?)", false);
        case ENAMETOOLONG:
            throw ReadFailure("the name is too long", false);
        default: {
            std::string why = std::strerror(error);
            if (!why.empty()) why[0] = static_cast<char>(std::tolower(why[0]));
            throw ReadFailure(why, false);
        }
    }
}

inline void requireRegular(const struct stat& st, std::size_t maxBytes) {
    if (S_ISDIR(st.st_mode)) throw ReadFailure("it is a folder", false);
    if (!S_ISREG(st.st_mode))
        throw ReadFailure("not a regular file (a device, a FIFO or a socket)", false);
    if (static_cast<std::uintmax_t>(st.st_size) > maxBytes)
        throw ReadFailure("larger than " + std::to_string(maxBytes >> 20) +
                              " MB, the most raystep reads of such a file",
                          false);
}

/// The bytes of a regular file of at most `maxBytes`; throws ReadFailure. The one way the core
/// opens a file: a folder, FIFO, device or socket is refused from stat() before it is opened,
/// and once more from fstat() of what was opened (O_NONBLOCK: opening cannot wait for a writer);
/// reading stops past `maxBytes`, should the file grow meanwhile.
inline std::string readRegularFile(const std::string& path, std::size_t maxBytes) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) throwReadFailure(errno);
    requireRegular(st, maxBytes);
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) throwReadFailure(errno);
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    if (::fstat(fd, &st) != 0) throwReadFailure(errno);
    requireRegular(st, maxBytes);
    std::string text;
    text.reserve(static_cast<std::size_t>(st.st_size));
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throwReadFailure(errno);
        if (n == 0) break;
        if (text.size() + static_cast<std::size_t>(n) > maxBytes)
            throw ReadFailure("larger than " + std::to_string(maxBytes >> 20) +
                                  " MB, the most raystep reads of such a file",
                              false);
        text.append(buffer, static_cast<std::size_t>(n));
    }
    return text;
}

inline std::string joinNames(std::initializer_list<const char*> names) {
    std::string out;
    for (const char* n : names) out += (out.empty() ? "" : ", ") + std::string(n);
    return out;
}

/// Typed access to the parsed JSON that fails with file, line and key.
template <typename Error>
class JsonReader {
  public:
    JsonReader(std::string file, JsonLineMap lines)
        : file_(std::move(file)), lines_(std::move(lines)) {}

    [[noreturn]] void fail(const std::string& path, const std::string& message) const {
        throw Error(file_, lines_.lineOf(path), path, message);
    }
    const JsonLineMap& lines() const { return lines_; }

    void requireObject(const json& j, const std::string& path) const {
        if (!j.is_object()) fail(path, "expected an object {...}, got " + typeName(j));
    }
    void checkKeys(const json& obj, const std::string& path,
                   std::initializer_list<const char*> allowed) const {
        for (const auto& [key, value] : obj.items()) {
            bool known = false;
            for (const char* a : allowed) known = known || key == a;
            if (!known)
                fail(JsonLineMap::child(path, key),
                     "unknown key (allowed here: " + joinNames(allowed) + ")");
        }
    }
    double number(const json& j, const std::string& path) const {
        if (!j.is_number()) fail(path, "expected a number, got " + typeName(j));
        const double v = j.get<double>();
        if (!std::isfinite(v)) fail(path, "must be a finite number");
        return v;
    }
    double positive(const json& j, const std::string& path) const {
        const double v = number(j, path);
        if (!(v > 0.0)) fail(path, "must be greater than 0, got " + fmt(v));
        return v;
    }
    double nonNegative(const json& j, const std::string& path) const {
        const double v = number(j, path);
        if (v < 0.0) fail(path, "must not be negative, got " + fmt(v));
        return v;
    }
    int integer(const json& j, const std::string& path, int lo, int hi) const {
        const double v = number(j, path);
        if (v != std::floor(v)) fail(path, "expected a whole number, got " + fmt(v));
        if (v < lo || v > hi)
            fail(path, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) +
                           ", got " + fmt(v));
        return static_cast<int>(v);
    }
    std::string string(const json& j, const std::string& path) const {
        if (!j.is_string()) fail(path, "expected a string, got " + typeName(j));
        return j.get<std::string>();
    }
    Vec3 vec3(const json& j, const std::string& path) const {
        if (!j.is_array() || j.size() != 3)
            fail(path, "expected an array of 3 numbers [x, y, z], got " + typeName(j));
        return Vec3(number(j[0], JsonLineMap::element(path, 0)),
                    number(j[1], JsonLineMap::element(path, 1)),
                    number(j[2], JsonLineMap::element(path, 2)));
    }
    /// A colour: [r, g, b] or one number for grey; each component >= 0 and, if `maxOne`, <= 1.
    Color color(const json& j, const std::string& path, bool maxOne) const {
        Color c;
        if (j.is_number()) {
            c = Color(number(j, path));
        } else if (j.is_array() && j.size() == 3) {
            c = vec3(j, path);
        } else {
            fail(path, "expected a colour: [r, g, b] or one number, got " + typeName(j));
        }
        for (int k = 0; k < 3; ++k) {
            if (c[k] < 0.0) fail(path, "colour components must not be negative");
            if (maxOne && c[k] > 1.0)
                fail(path, "reflectance components must be at most 1 (energy conservation)");
        }
        return c;
    }

    static std::string typeName(const json& j) {
        if (j.is_null()) return "null";
        if (j.is_boolean()) return "a boolean";
        if (j.is_number()) return "a number";
        if (j.is_string()) return "a string";
        if (j.is_array()) return "an array of " + std::to_string(j.size());
        return "an object";
    }
    static std::string fmt(double v) {
        std::ostringstream s;
        s << v;
        return s.str();
    }

  private:
    std::string file_;
    JsonLineMap lines_;
};

/// Runs `f(value, path)` on obj[key] when present.
template <typename F>
inline void ifPresent(const json& obj, const std::string& path, const char* key, F&& f) {
    if (auto it = obj.find(key); it != obj.end()) f(*it, JsonLineMap::child(path, key));
}

/// A parsed file: the tree, and where each of its keys stands.
template <typename Json>
struct ParsedJson {
    Json root;
    JsonLineMap lines;
};

/// Parses JSON (with comments unless `comments` is false); a syntax error, an out-of-range
/// number, nesting past kMaxJsonDepth or a key given twice becomes one Error naming the line.
/// The depth is checked before nlohmann sees the text: its copies and comparisons recurse.
template <typename Error, typename Json = json>
ParsedJson<Json> parseJsonFile(std::string_view text, const std::string& fileName,
                               bool comments = true) {
    // nlohmann stops reading at a NUL byte and accepts what came before: refuse it here (JSON
    // allows none outside a string, and none raw inside one).
    if (const auto nul = text.find('\0'); nul != std::string_view::npos)
        throw Error(fileName,
                    1 + static_cast<int>(std::count(text.begin(), text.begin() + nul, '\n')), "",
                    "a NUL byte: a JSON file is text");
    JsonLineMap lines(text);
    if (const int line = lines.tooDeepLine())
        throw Error(
            fileName, line, "",
            "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels of [ ] and { }");
    Json root;
    try {
        root = Json::parse(text.begin(), text.end(), nullptr, true, /*ignore_comments=*/comments);
    } catch (const nlohmann::json::out_of_range& e) {
        // A number too large for a double ("1e999"): nlohmann names the token, not the place.
        std::string what = e.what();
        const auto q0 = what.find('\'');
        const auto q1 = what.rfind('\'');
        const std::string token = q0 < q1 ? what.substr(q0 + 1, q1 - q0 - 1) : std::string();
        const auto at = token.empty() ? std::string_view::npos : text.find(token);
        const int line =
            at == std::string_view::npos
                ? 1
                : 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
        throw Error(fileName, line, "",
                    "number '" + printable(token, 24) + "' is out of range: values must be finite");
    } catch (const nlohmann::json::parse_error& e) {
        // nlohmann says "[json.exception.parse_error.101] parse error at line L, column C: ...
        // last read: 'TOKEN'; expected ...": the token may be a whole unterminated string.
        std::string what = e.what();
        const auto at = what.find("parse error");
        what = at == std::string::npos ? what : what.substr(at);
        const std::string lastRead = "last read: '";
        if (const auto from = what.find(lastRead); from != std::string::npos) {
            const auto start = from + lastRead.size();
            auto end = what.rfind("'; ");
            if (end == std::string::npos || end < start) end = what.rfind('\'');
            if (end != std::string::npos && end >= start)
                what.replace(start, end - start,
                             printable(std::string_view(what).substr(start, end - start), 40));
        }
        // Line of the failing byte, counted here so the message starts like every other one.
        int line = 1;
        for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) line += text[i] == '\n';
        throw Error(fileName, line, "", "malformed JSON: " + what);
    } catch (const nlohmann::json::exception& e) {
        throw Error(fileName, 1, "", std::string("malformed JSON: ") + e.what());
    }
    if (!lines.duplicates().empty()) {
        const auto& [path, line] = lines.duplicates().front();
        throw Error(fileName, line, path, "key given twice");
    }
    return {std::move(root), std::move(lines)};
}

/// Runs a reader: an nlohmann exception that got past its checks (a bug) still ends as one
/// Error naming the file, never as another exception type.
template <typename Error, typename F>
auto guarded(const std::string& fileName, F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const nlohmann::json::exception& e) {
        throw Error(fileName, 0, "", std::string("cannot read the file: ") + e.what());
    }
}

}  // namespace raystep::detail

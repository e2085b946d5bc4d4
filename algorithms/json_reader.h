#pragma once
// Reading a file (scene or lesson) so that every error names the file, the line and the key:
// typed accessors over nlohmann::json that throw the loader's own error type. Internal to the core.
#include "raystep/json_lines.h"
#include "raystep/math.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

namespace raystep::detail {

using nlohmann::json;

/// A whole file's bytes, or nullopt when it cannot be read (missing, a folder).
inline std::optional<std::string> readWholeFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in || std::filesystem::is_directory(path)) return std::nullopt;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
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
    JsonReader(std::string file, std::string_view text) : file_(std::move(file)), lines_(text) {}

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

/// Parses JSON with comments; a syntax error or an out-of-range number becomes one Error naming
/// the line. Duplicate keys are an error too (JSON would keep the last silently).
template <typename Error>
json parseJsonFile(std::string_view text, const std::string& fileName) {
    json root;
    try {
        root = json::parse(text.begin(), text.end(), nullptr, true, /*ignore_comments=*/true);
    } catch (const json::out_of_range& e) {
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
                    "number '" + token + "' is out of range: values must be finite");
    } catch (const json::parse_error& e) {
        // nlohmann says "[json.exception.parse_error.101] parse error at line L, column C: ...".
        std::string what = e.what();
        const auto at = what.find("parse error");
        what = at == std::string::npos ? what : what.substr(at);
        // Line of the failing byte, counted here so the message starts like every other one.
        int line = 1;
        for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) line += text[i] == '\n';
        throw Error(fileName, line, "", "malformed JSON: " + what);
    }
    const JsonLineMap lines(text);
    if (!lines.duplicates().empty()) {
        const auto& [path, line] = lines.duplicates().front();
        throw Error(fileName, line, path, "key given twice");
    }
    return root;
}

}  // namespace raystep::detail

#pragma once
// The words of an OBJ file, as both OBJ readers (tinyobjloader for a scene's meshes, assimp for
// models) must be given them: the same number grammar and fields for the scene loader's checks
// and the model importer's, so that one file gets one answer.
#include <algorithm>
#include <string_view>
#include <vector>

namespace raystep::detail {

/// A whole number as tinyobjloader's parseTriple reads one with atoi: [+-]digits.
inline bool isObjInteger(std::string_view s) {
    if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.remove_prefix(1);
    return !s.empty() &&
           std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

/// A number in the grammar tinyobjloader's tryParseDouble reads ([+-] digits [. digits] [e[+-]
/// digits], or [+-] . digits ...), taken whole, so strtod and the OBJ readers agree on what it
/// is (tinyobjloader would read "0x10" as 0, assimp "abc" and "1,5" as 0 and 1).
inline bool isObjNumber(std::string_view s) {
    std::size_t i = 0;
    const auto digits = [&] {
        const std::size_t from = i;
        while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
        return i > from;
    };
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    bool mantissa = digits();
    if (i < s.size() && s[i] == '.') {
        ++i;
        mantissa = digits() || mantissa;
    }
    if (!mantissa) return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        if (!digits()) return false;
    }
    return i == s.size();
}

/// The blank- or tab-separated fields of a statement, up to a '#' comment.
inline std::vector<std::string_view> objFields(std::string_view rest) {
    std::vector<std::string_view> fields;
    std::size_t i = 0;
    while (i < rest.size()) {
        while (i < rest.size() && (rest[i] == ' ' || rest[i] == '\t')) ++i;
        if (i >= rest.size() || rest[i] == '#') break;
        const std::size_t from = i;
        while (i < rest.size() && rest[i] != ' ' && rest[i] != '\t') ++i;
        fields.push_back(rest.substr(from, i - from));
    }
    return fields;
}

/// A face's corner "i", "i/j", "i//k" or "i/j/k": its three parts (empty when not given);
/// false when it is none of these forms.
inline bool splitObjCorner(std::string_view f, std::string_view& v, std::string_view& vt,
                           std::string_view& vn) {
    const std::size_t slash = f.find('/');
    v = f.substr(0, slash);
    vt = vn = {};
    if (!isObjInteger(v)) return false;
    if (slash == std::string_view::npos) return true;
    const std::string_view rest = f.substr(slash + 1);
    const std::size_t slash2 = rest.find('/');
    vt = rest.substr(0, slash2);
    if (slash2 == std::string_view::npos) return isObjInteger(vt);
    vn = rest.substr(slash2 + 1);
    return (vt.empty() || isObjInteger(vt)) && isObjInteger(vn);
}

/// Most corners a face may have, in both OBJ paths: both readers' ear clipping is cubic in it
/// (assimp took 4 s for one 32,000-gon).
constexpr std::size_t kMaxFaceVertices = 256;

}  // namespace raystep::detail

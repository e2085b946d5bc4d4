#include "raystep/scene/model_checks.h"

#include "raystep/base/json_reader.h"
#include "raystep/scene/obj_text.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <set>

namespace raystep::detail {

namespace {

[[noreturn]] void refuse(const std::string& file, int line, const std::string& message,
                         const std::string& key = {}) {
    throw SceneError(file, line, key, message);
}

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

std::string extensionOf(const std::string& path) {
    return lower(std::filesystem::path(path).extension().string());
}

std::string ordinal(std::uint64_t i) {
    return "number " + std::to_string(i);
}

/// A decimal whole number of at most `max`, digits only (no sign, blank or exponent).
std::optional<std::uint64_t> wholeNumber(std::string_view s, std::uint64_t max) {
    if (s.empty() || s.size() > 20 ||
        !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return std::nullopt;
    std::uint64_t v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || v > max) return std::nullopt;
    return v;
}

std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const std::size_t from = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > from) out.push_back(line.substr(from, i - from));
    }
    return out;
}

// ---------------------------------------------------------------------------------------------
// PLY: the header read here in full (assimp's header parser looped for ever, or read past its
// buffer, on a header without an end_header line of its own), then the body walked as the
// header describes it, so that every count assimp will reserve for is there in the file.

enum class PlyType : std::uint8_t { I8, U8, I16, U16, I32, U32, F32, F64 };

std::optional<PlyType> plyType(std::string_view t) {
    static const std::array<std::pair<std::string_view, PlyType>, 16> names = {{
        {"char", PlyType::I8},
        {"int8", PlyType::I8},
        {"uchar", PlyType::U8},
        {"uint8", PlyType::U8},
        {"short", PlyType::I16},
        {"int16", PlyType::I16},
        {"ushort", PlyType::U16},
        {"uint16", PlyType::U16},
        {"int", PlyType::I32},
        {"int32", PlyType::I32},
        {"uint", PlyType::U32},
        {"uint32", PlyType::U32},
        {"float", PlyType::F32},
        {"float32", PlyType::F32},
        {"double", PlyType::F64},
        {"float64", PlyType::F64},
    }};
    for (const auto& [name, type] : names)
        if (name == t) return type;
    return std::nullopt;
}

std::size_t plySize(PlyType t) {
    switch (t) {
        case PlyType::I8:
        case PlyType::U8:
            return 1;
        case PlyType::I16:
        case PlyType::U16:
            return 2;
        case PlyType::F64:
            return 8;
        default:
            return 4;
    }
}

bool plyFloat(PlyType t) {
    return t == PlyType::F32 || t == PlyType::F64;
}

std::pair<std::int64_t, std::int64_t> plyRange(PlyType t) {
    switch (t) {
        case PlyType::I8:
            return {-128, 127};
        case PlyType::U8:
            return {0, 255};
        case PlyType::I16:
            return {-32768, 32767};
        case PlyType::U16:
            return {0, 65535};
        case PlyType::I32:
            return {INT32_MIN, INT32_MAX};
        default:
            return {0, UINT32_MAX};
    }
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::F32;
    bool list = false;
    PlyType countType = PlyType::U8;
    bool faceIndices = false;  // a face's corners: at most kMaxFaceVertices, each a vertex
    bool coordinate = false;   // a vertex's x, y or z: finite as a float
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    int line = 0;
    std::vector<PlyProperty> properties;
    bool hasList() const {
        return std::any_of(properties.begin(), properties.end(),
                           [](const PlyProperty& p) { return p.list; });
    }
};

enum class PlyFormat { Ascii, LittleEndian, BigEndian };

/// Most instances of an element raystep does not use (a camera, materials, edges): assimp keeps
/// each as objects of its own (about 100 bytes an instance whatever its size in the file).
constexpr std::uint64_t kMaxOtherPlyElements = 1'000'000;
/// A list that is no face's corners (a triangle strip): at most this long.
constexpr std::uint64_t kMaxPlyList = 1u << 24;

class PlyBody {
  public:
    PlyBody(const std::string& file, std::string_view bytes, std::size_t at, PlyFormat format,
            int line)
        : file_(file), bytes_(bytes), at_(at), format_(format), line_(line) {}

    void walk(const std::vector<PlyElement>& elements, std::uint64_t vertices) {
        std::uint64_t triangles = 0;
        for (const PlyElement& e : elements) {
            if (e.properties.empty()) continue;  // and none of them (checkPly)
            // Fixed-size rows in binary: one comparison (unless x, y, z are to be looked at).
            const bool coordinates = std::any_of(e.properties.begin(), e.properties.end(),
                                                 [](const PlyProperty& p) { return p.coordinate; });
            if (format_ != PlyFormat::Ascii && !e.hasList() && !coordinates) {
                std::uint64_t row = 0;
                for (const PlyProperty& p : e.properties) row += plySize(p.type);
                if (e.count > (bytes_.size() - at_) / row)
                    refuse(file_, e.line,
                           "the PLY header declares " + std::to_string(e.count) + " '" +
                               printable(e.name, 24) + "' elements of " + std::to_string(row) +
                               " bytes, more than the " + std::to_string(bytes_.size() - at_) +
                               " bytes after it hold");
                at_ += e.count * row;
                continue;
            }
            for (std::uint64_t k = 0; k < e.count; ++k)
                for (const PlyProperty& p : e.properties) {
                    if (!p.list) {
                        value(e, k, p, p.type);
                        continue;
                    }
                    const double n = value(e, k, p, p.countType, true);
                    if (n < 0)
                        fail(e, k,
                             "property '" + printable(p.name, 24) + "': a list of " + number(n) +
                                 " values");
                    const auto count = static_cast<std::uint64_t>(n);
                    if (p.faceIndices && count > kMaxFaceVertices)
                        fail(e, k,
                             "a face has at most " + std::to_string(kMaxFaceVertices) +
                                 " vertices, this one " + std::to_string(count));
                    if (count > kMaxPlyList)
                        fail(e, k,
                             "property '" + printable(p.name, 24) + "': a list of " +
                                 std::to_string(count) + " values, more than raystep reads");
                    if (p.faceIndices && count > 2) {
                        triangles += count - 2;
                        if (triangles > kMaxModelTriangles)
                            fail(e, k,
                                 "more than " + std::to_string(kMaxModelTriangles) +
                                     " triangles, the most raystep reads from one model");
                    }
                    for (std::uint64_t j = 0; j < count; ++j) {
                        const double index = value(e, k, p, p.type);
                        if (p.faceIndices && !(index >= 0 && index < double(vertices)))
                            fail(e, k,
                                 "vertex index " + number(index) + " is out of range (" +
                                     std::to_string(vertices) + " vertices)");
                    }
                }
        }
    }

  private:
    [[noreturn]] void fail(const PlyElement& e, std::uint64_t k, const std::string& message) {
        refuse(file_, format_ == PlyFormat::Ascii ? line_ : 0,
               "element '" + printable(e.name, 24) + "' " + ordinal(k) + " (counting from 0)" +
                   (format_ == PlyFormat::Ascii ? "" : " at byte " + std::to_string(at_)) + ": " +
                   message);
    }
    static std::string number(double v) {
        char buf[32];
        const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
        return std::string(buf, ec == std::errc() ? end : buf);
    }
    [[noreturn]] void ended(const PlyElement& e, std::uint64_t k) {
        refuse(file_, e.line,
               "the PLY header declares " + std::to_string(e.count) + " '" + printable(e.name, 24) +
                   "' elements, but the file ends inside " + ordinal(k) + " (counting from 0)");
    }

    /// The next value of type `t`, checked: a number of its type (ASCII), in its range.
    double value(const PlyElement& e, std::uint64_t k, const PlyProperty& p, PlyType t,
                 bool count = false) {
        const std::string what =
            "property '" + printable(p.name, 24) + "'" + (count ? " (the list's length)" : "");
        double v = 0;
        if (format_ == PlyFormat::Ascii) {
            const std::string_view word = nextWord();
            if (word.empty()) ended(e, k);
            if (plyFloat(t)) {
                const std::string text(word);
                v = isObjNumber(word) ? std::strtod(text.c_str(), nullptr) : NAN;
                if (!std::isfinite(v))
                    fail(e, k, what + ": '" + printable(word, 24) + "' is not a finite number");
            } else {
                std::int64_t i = 0;
                const char* first = word.data() + (word[0] == '+');
                const auto [ptr, ec] = std::from_chars(first, word.data() + word.size(), i);
                if (ec != std::errc() || ptr != word.data() + word.size())
                    fail(e, k, what + ": '" + printable(word, 24) + "' is not a whole number");
                const auto [lo, hi] = plyRange(t);
                if (i < lo || i > hi)
                    fail(e, k,
                         what + ": " + std::to_string(i) + " does not fit its type (" +
                             std::to_string(lo) + " to " + std::to_string(hi) + ")");
                v = double(i);
            }
        } else {
            const std::size_t size = plySize(t);
            if (bytes_.size() - at_ < size) ended(e, k);
            std::array<unsigned char, 8> b{};
            std::memcpy(b.data(), bytes_.data() + at_, size);
            if (format_ == PlyFormat::BigEndian) std::reverse(b.begin(), b.begin() + size);
            at_ += size;
            switch (t) {
                case PlyType::I8:
                    v = static_cast<std::int8_t>(b[0]);
                    break;
                case PlyType::U8:
                    v = b[0];
                    break;
                case PlyType::I16: {
                    std::int16_t x;
                    std::memcpy(&x, b.data(), 2);
                    v = x;
                    break;
                }
                case PlyType::U16: {
                    std::uint16_t x;
                    std::memcpy(&x, b.data(), 2);
                    v = x;
                    break;
                }
                case PlyType::I32: {
                    std::int32_t x;
                    std::memcpy(&x, b.data(), 4);
                    v = x;
                    break;
                }
                case PlyType::U32: {
                    std::uint32_t x;
                    std::memcpy(&x, b.data(), 4);
                    v = x;
                    break;
                }
                case PlyType::F32: {
                    float x;
                    std::memcpy(&x, b.data(), 4);
                    v = x;
                    break;
                }
                case PlyType::F64:
                    std::memcpy(&v, b.data(), 8);
                    break;
            }
        }
        // assimp keeps a vertex in float: a double past its range would be infinite.
        if (p.coordinate && !count && !(std::abs(v) <= FLT_MAX))
            fail(e, k,
                 what + ": " +
                     (std::isfinite(v) ? number(v) + " is past the largest float"
                                       : std::string("not a finite number")));
        return v;
    }

    std::string_view nextWord() {
        const auto blank = [](char c) {
            return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
        };
        while (at_ < bytes_.size() && blank(bytes_[at_])) line_ += bytes_[at_++] == '\n';
        const std::size_t from = at_;
        while (at_ < bytes_.size() && !blank(bytes_[at_])) {
            if (bytes_[at_] == '\0') refuse(file_, line_, "a NUL byte in an ASCII PLY file");
            ++at_;
        }
        return bytes_.substr(from, at_ - from);
    }

    const std::string& file_;
    std::string_view bytes_;
    std::size_t at_;
    PlyFormat format_;
    int line_;
};

}  // namespace

void checkPly(const std::string& file, std::string_view bytes) {
    if (!bytes.starts_with("ply\n") && !bytes.starts_with("ply\r\n")) {
        std::size_t i = 0;
        while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
        if (bytes.starts_with("ply\r"))
            refuse(file, 1,
                   "the PLY header's lines end with CR alone; PLY lines end with LF (or CR LF)");
        if (lower(bytes.substr(i, 3)) == "ply")
            refuse(file, 1, "a PLY file begins with the line 'ply', in lower case, first");
        refuse(file, 1, "not a PLY file: it does not begin with the line 'ply'");
    }
    std::optional<PlyFormat> format;
    std::vector<PlyElement> elements;
    std::size_t pos = 0;
    int line = 0;
    bool ended = false;
    while (pos < bytes.size()) {
        ++line;
        std::size_t eol = bytes.find('\n', pos);
        if (eol == std::string_view::npos) eol = bytes.size();
        std::string_view text = bytes.substr(pos, eol - pos);
        pos = std::min(eol + 1, bytes.size());
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        if (line == 1) continue;  // "ply"
        if (text.find('\r') != std::string_view::npos)
            refuse(file, line, "a CR inside a header line (PLY lines end with LF or CR LF)");
        // Data before any end_header: binary bytes, or numbers on a line of their own.
        const std::size_t first = text.find_first_not_of(" \t");
        if (text.find('\0') != std::string_view::npos ||
            (first != std::string_view::npos &&
             (std::isdigit(static_cast<unsigned char>(text[first])) || text[first] == '-')))
            refuse(file, line,
                   "data where the header goes on: the PLY header has no 'end_header' line (a "
                   "line of its own ending the header) before it");
        const auto w = words(text);
        if (w.empty()) continue;
        const std::string_view keyword = w[0];
        if (keyword == "comment" || keyword == "obj_info") continue;
        if (keyword == "end_header") {
            if (w.size() != 1) refuse(file, line, "'end_header' stands alone on its line");
            ended = true;
            break;
        }
        if (keyword == "format") {
            if (format) refuse(file, line, "a second format line");
            if (w.size() != 3 || w[2] != "1.0" ||
                (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
                refuse(file, line,
                       "the format is 'format ascii 1.0', 'format binary_little_endian 1.0' or "
                       "'format binary_big_endian 1.0'");
            format = w[1] == "ascii"                  ? PlyFormat::Ascii
                     : w[1] == "binary_little_endian" ? PlyFormat::LittleEndian
                                                      : PlyFormat::BigEndian;
            continue;
        }
        if (keyword == "element") {
            if (!format) refuse(file, line, "an element before the format line");
            if (w.size() != 3) refuse(file, line, "an element is 'element NAME COUNT'");
            const auto count = wholeNumber(w[2], UINT32_MAX);
            if (!count)
                refuse(file, line,
                       "element '" + printable(w[1], 24) + "': its count '" + printable(w[2], 24) +
                           "' is not a whole number from 0 to 4294967295");
            for (const PlyElement& e : elements)
                if (e.name == w[1])
                    refuse(file, line, "a second element named '" + printable(w[1], 24) + "'");
            elements.push_back({std::string(w[1]), *count, line, {}});
            continue;
        }
        if (keyword == "property") {
            if (elements.empty()) refuse(file, line, "a property before any element");
            PlyProperty p;
            const bool list = w.size() >= 2 && w[1] == "list";
            if (w.size() != (list ? 5u : 3u))
                refuse(file, line,
                       "a property is 'property TYPE NAME' or 'property list COUNT_TYPE TYPE "
                       "NAME'");
            const auto type = plyType(w[list ? 3 : 1]);
            const auto countType = list ? plyType(w[2]) : std::optional<PlyType>(PlyType::U8);
            if (!type || !countType)
                refuse(file, line,
                       "unknown property type '" +
                           printable(w[!countType ? 2
                                       : list     ? 3
                                                  : 1],
                                     24) +
                           "' (char, uchar, short, ushort, int, uint, float, double, or int8 "
                           "... float64)");
            if (plyFloat(*countType))
                refuse(file, line, "a list's length is a whole-number type, not a float");
            p.name = std::string(w[list ? 4 : 2]);
            p.type = *type;
            p.list = list;
            p.countType = *countType;
            PlyElement& e = elements.back();
            p.faceIndices = list && e.name == "face" &&
                            (p.name == "vertex_indices" || p.name == "vertex_index");
            p.coordinate = !list && e.name == "vertex" && plyFloat(p.type) &&
                           (p.name == "x" || p.name == "y" || p.name == "z");
            e.properties.push_back(p);
            continue;
        }
        refuse(file, line,
               "'" + printable(keyword, 24) +
                   "' is no PLY header statement (format, comment, obj_info, element, property, "
                   "end_header)");
    }
    if (!ended)
        refuse(file, line,
               "the PLY header has no 'end_header' line (a line of its own ending the header)");
    if (!format) refuse(file, line, "the PLY header has no format line");
    std::uint64_t vertices = 0;
    for (const PlyElement& e : elements) {
        if (e.properties.empty() && e.count > 0)
            refuse(file, e.line,
                   "element '" + printable(e.name, 24) +
                       "' has no properties: " + std::to_string(e.count) + " instances of nothing");
        const std::uint64_t cap = e.name == "vertex" ? kMaxModelVertices
                                  : e.name == "face" ? kMaxModelTriangles
                                                     : kMaxOtherPlyElements;
        if (e.count > cap)
            refuse(file, e.line,
                   "the PLY header declares " + std::to_string(e.count) + " '" +
                       printable(e.name, 24) + "' elements, more than the " + std::to_string(cap) +
                       " raystep reads");
        if (e.name == "vertex") vertices = e.count;
    }
    PlyBody(file, bytes, pos, *format, line + 1).walk(elements, vertices);
}

// ---------------------------------------------------------------------------------------------
// STL: binary when its size is 84 + 50 bytes a triangle, ASCII when it begins with "solid", as
// assimp decides; anything else is refused here.

void checkStl(const std::string& file, std::string_view bytes) {
    if (bytes.size() >= 84) {
        std::uint32_t n = 0;
        std::memcpy(&n, bytes.data() + 80, 4);
        const std::uint64_t expected = 84 + 50 * std::uint64_t(n);
        if (expected == bytes.size()) return;  // binary, and as long as its count says
        // assimp compares in 32 bits: a huge count wraps to the file's size and is believed.
        if (static_cast<std::uint32_t>(expected) == bytes.size())
            refuse(file, 0,
                   "a binary STL whose header says " + std::to_string(n) + " triangles: that is " +
                       std::to_string(expected) + " bytes, the file has " +
                       std::to_string(bytes.size()));
    }
    std::size_t i = 0;
    while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
    if (bytes.substr(i, 5) != "solid") {
        std::string binary = "shorter than the 84 bytes of a binary STL's header";
        if (bytes.size() >= 84) {
            std::uint32_t n = 0;
            std::memcpy(&n, bytes.data() + 80, 4);
            binary = "a binary STL's header says " + std::to_string(n) + " triangles, which take " +
                     std::to_string(84 + 50 * std::uint64_t(n)) + " bytes; the file has " +
                     std::to_string(bytes.size());
        }
        refuse(file, 0, "not an STL file: not ASCII (which begins with 'solid'), and " + binary);
    }
    // ASCII: every vertex's three numbers in the grammar assimp reads right (it reads "abc" as 0).
    int line = 1;
    std::size_t pos = 0;
    while (pos < bytes.size()) {
        std::size_t eol = bytes.find('\n', pos);
        if (eol == std::string_view::npos) eol = bytes.size();
        const std::string_view text = bytes.substr(pos, eol - pos);
        if (text.find('\0') != std::string_view::npos)
            refuse(file, line,
                   "a NUL byte in an ASCII STL file (its size does not fit a binary one)");
        std::vector<std::string_view> w;
        for (std::size_t k = 0; k < text.size();) {
            while (k < text.size() && std::isspace(static_cast<unsigned char>(text[k]))) ++k;
            const std::size_t from = k;
            while (k < text.size() && !std::isspace(static_cast<unsigned char>(text[k]))) ++k;
            if (k > from) w.push_back(text.substr(from, k - from));
        }
        if (!w.empty() && w[0] == "vertex") {
            if (w.size() != 4) refuse(file, line, "a vertex is 'vertex x y z'");
            for (int k = 1; k < 4; ++k) {
                const std::string t(w[k]);
                const double v = isObjNumber(w[k]) ? std::strtod(t.c_str(), nullptr) : NAN;
                if (!(std::abs(v) <= FLT_MAX))
                    refuse(file, line,
                           "vertex coordinate '" + printable(w[k], 24) +
                               (std::isfinite(v) ? "' is past the largest float"
                                                 : "' is not a finite number"));
            }
        }
        pos = eol + 1;
        ++line;
    }
}

// ---------------------------------------------------------------------------------------------
// OBJ, as assimp's ObjFileParser reads it (not as tinyobjloader does): a line ends at LF, CR or
// form feed; its first character says what it is ('v', 'f', 'l', 'p' ...; a line beginning
// with a blank is skipped); a vertex counts only with 3, 4 or 6 numbers, each beginning with a
// digit or a sign; a face's indices are read digit by digit. Where assimp's reading would differ
// from the file's plain meaning, or cost without bound, the line is refused here.

namespace {

/// Most objects, groups and material changes: each becomes a mesh (and a node) of its own.
constexpr std::uint64_t kMaxObjMeshes = 100'000;

template <typename F>
void forEachAssimpObjLine(const std::string& file, std::string_view text, F&& f) {
    int lineNo = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        ++lineNo;
        std::size_t end = pos;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r' && text[end] != '\f')
            ++end;
        const std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        if (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n') ++pos;
        if (line.find('\0') != std::string_view::npos)
            refuse(file, lineNo, "a NUL byte: not a text file");
        if (!line.empty() && line.back() == '\\')
            refuse(file, lineNo,
                   "a line continued with '\\': raystep reads an OBJ model's lines one by one");
        f(lineNo, line);
    }
}

bool objBlank(char c) {
    return c == ' ' || c == '\t';
}

/// An index as assimp reads it (atoi, then as many characters as its digits): [-]digits, no
/// '+' and no leading zero, else assimp reads the rest again as another index.
bool isAssimpIndex(std::string_view s) {
    if (!s.empty() && s[0] == '-') s.remove_prefix(1);
    return !s.empty() && s[0] >= '1' && s[0] <= '9' &&
           std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

void checkObj(const std::string& file, std::string_view text) {
    // Forward references are legal (assimp checks indices against the final counts).
    std::array<std::uint64_t, 3> total{};  // v, vt, vn
    forEachAssimpObjLine(file, text, [&](int, std::string_view line) {
        if (line.size() >= 2 && line[0] == 'v') {
            if (objBlank(line[1])) ++total[0];
            if (line[1] == 't') ++total[1];
            if (line[1] == 'n') ++total[2];
        }
    });
    std::array<std::uint64_t, 3> sofar{};
    std::uint64_t triangles = 0, pointsAndLines = 0, meshes = 0;
    static const std::array<const char*, 3> kinds = {"vertex", "texture coordinate", "normal"};
    static const std::array<const char*, 3> plurals = {"vertices", "texture coordinates",
                                                       "normals"};
    forEachAssimpObjLine(file, text, [&](int lineNo, std::string_view line) {
        if (line.empty()) return;
        const char first = line[0];
        if (first == 'v' && line.size() >= 2 &&
            (objBlank(line[1]) || line[1] == 't' || line[1] == 'n')) {
            const int kind = objBlank(line[1]) ? 0 : line[1] == 't' ? 1 : 2;
            // Every field up to a '#' comment, as the scene loader reads them (assimp is given
            // the line without its comment: blankObjComments).
            const auto fields = objFields(line.substr(objBlank(line[1]) ? 1 : 2));
            const std::size_t n = fields.size();
            if (kind == 0 && n != 3 && n != 4 && n != 6)
                refuse(file, lineNo,
                       "a vertex is 'v x y z' (or 4 numbers, or 6 with a colour), this one has " +
                           std::to_string(n) + " fields");
            if (kind == 1 && (n < 1 || n > 3))
                refuse(file, lineNo, "a texture coordinate is 'vt u [v [w]]'");
            if (kind == 2 && n != 3) refuse(file, lineNo, "a normal is 'vn x y z'");
            for (const std::string_view f : fields) {
                const std::string token(f);
                const double v = isObjNumber(f) ? std::strtod(token.c_str(), nullptr) : NAN;
                if (f[0] == '.')
                    refuse(file, lineNo,
                           std::string(kinds[kind]) + " coordinate '" + printable(f, 24) +
                               "': write a digit before the point (0.5, not .5); assimp would "
                               "leave the number out");
                if (!std::isfinite(v))
                    refuse(file, lineNo,
                           std::string(kinds[kind]) + " coordinate '" + printable(f, 24) +
                               "' is not a finite number");
                if (!(std::abs(v) <= FLT_MAX))
                    refuse(file, lineNo,
                           std::string(kinds[kind]) + " coordinate '" + printable(f, 24) +
                               "' is past the largest float (3.4e38), where the model importer "
                               "keeps it");
            }
            ++sofar[std::size_t(kind)];
            return;
        }
        if (first == 'f' || first == 'l' || first == 'p') {
            // assimp reads any line beginning with f, l or p as a face, a line or points.
            if (line.size() < 2 || !objBlank(line[1]))
                refuse(file, lineNo,
                       "'" + printable(words(line)[0], 24) +
                           "' is no statement raystep reads (assimp would read the line as " +
                           (first == 'f'   ? "a face"
                            : first == 'l' ? "a line"
                                           : "points") +
                           ")");
            const auto fields = objFields(line.substr(1));
            if (first == 'f' && fields.size() < 3)
                refuse(file, lineNo, "a face needs at least 3 vertices");
            if (fields.empty()) refuse(file, lineNo, "no vertices");
            if (fields.size() > kMaxFaceVertices)
                refuse(file, lineNo,
                       std::string(first == 'f'   ? "a face"
                                   : first == 'l' ? "a line"
                                                  : "a point "
                                                    "statement") +
                           " has at most " + std::to_string(kMaxFaceVertices) +
                           " vertices, this one " + std::to_string(fields.size()));
            if (first == 'f') {
                triangles += fields.size() - 2;
                if (triangles > kMaxModelTriangles)
                    refuse(file, lineNo,
                           "more than " + std::to_string(kMaxModelTriangles) +
                               " triangles, the most raystep reads from one model");
            } else {
                pointsAndLines += fields.size();
                if (pointsAndLines > kMaxModelPointsAndLines)
                    refuse(file, lineNo,
                           "more than " + std::to_string(kMaxModelPointsAndLines) +
                               " points and line vertices, the most raystep reads from one model");
            }
            for (const std::string_view f : fields) {
                std::array<std::string_view, 3> part;
                const bool ok = splitObjCorner(f, part[0], part[1], part[2]) &&
                                std::all_of(part.begin(), part.end(), [](std::string_view p) {
                                    return p.empty() || isAssimpIndex(p);
                                });
                if (!ok || (first == 'p' && f.find('/') != std::string_view::npos))
                    refuse(file, lineNo,
                           "face vertex '" + printable(f, 24) +
                               "' is not an index (i, i/j, i//k or i/j/k; no '+', no leading 0)");
                for (std::size_t k = 0; k < 3; ++k) {
                    if (part[k].empty()) continue;
                    std::int64_t index = 0;
                    const auto [ptr, ec] =
                        std::from_chars(part[k].data(), part[k].data() + part[k].size(), index);
                    const bool negative = ec == std::errc() && index < 0;
                    const std::uint64_t count = negative ? sofar[k] : total[k];
                    if (ec != std::errc() ||
                        (negative ? static_cast<std::uint64_t>(-(index + 1)) + 1 > count
                                  : static_cast<std::uint64_t>(index) > count))
                        refuse(file, lineNo,
                               std::string(kinds[k]) + " index " + printable(part[k], 24) +
                                   " is out of range (" + std::to_string(count) + " " + plurals[k] +
                                   (negative ? " before this line)" : ")"));
                }
            }
            return;
        }
        if (first == 'o' || first == 'g' || line.starts_with("usemtl")) {
            if (++meshes > kMaxObjMeshes)
                refuse(file, lineNo,
                       "more than " + std::to_string(kMaxObjMeshes) +
                           " objects, groups and material changes (o, g, usemtl): each is a mesh "
                           "of its own");
        }
    });
}

void blankObjComments(std::string& text) {
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = pos;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r' && text[end] != '\f')
            ++end;
        // A comment begins a field (after a blank), on a line that is no comment itself.
        if (end > pos && text[pos] != '#')
            for (std::size_t i = pos + 1; i < end; ++i)
                if (text[i] == '#' && objBlank(text[i - 1])) {
                    std::fill(text.begin() + std::ptrdiff_t(i), text.begin() + std::ptrdiff_t(end),
                              ' ');
                    break;
                }
        pos = end + 1;
    }
}

// ---------------------------------------------------------------------------------------------
// glTF 2.0: the JSON through raystep's own parser (nesting capped, keys given twice refused),
// then what assimp would build from it counted before it builds anything: node trees (no node
// with two parents, no cycle, no deeper than kMaxGltfNodeDepth), every primitive's vertices and
// triangles and every instance's, the buffers' sizes against their files and their sum.

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A, kChunkBin = 0x004E4942;
/// Accessor elements (of any type) all primitives, morph targets and animations may hold.
constexpr std::uint64_t kMaxGltfElements = 64'000'000;

std::uint32_t le32(std::string_view b, std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, b.data() + at, 4);
    return v;
}

struct GlbParts {
    std::string_view json;
    std::uint64_t binBytes = 0;
    bool hasBin = false;
};

GlbParts splitGlb(const std::string& file, std::string_view b) {
    // The smallest glb: its 12-byte header, the JSON chunk's 8-byte header, 8 bytes of JSON.
    constexpr std::uint64_t kMinGlb = 28;
    if (b.size() < kMinGlb)
        refuse(file, 0,
               "a glb file is at least 28 bytes (its header, its JSON chunk's header and the "
               "JSON), this one " +
                   std::to_string(b.size()));
    // In 64 bits: a header length below 20 wrapped round in 32 (length - 20).
    const std::uint64_t version = le32(b, 4), length = le32(b, 8);
    if (version != 2)
        refuse(file, 0, "glb version " + std::to_string(version) + ": raystep reads glTF 2.0");
    if (length < kMinGlb)
        refuse(file, 0,
               "the glb's header says " + std::to_string(length) +
                   " bytes; a glb is at least 28 (its header, its JSON chunk's header and the "
                   "JSON)");
    if (length > b.size())
        refuse(file, 0,
               "the glb's header says " + std::to_string(length) + " bytes, the file has " +
                   std::to_string(b.size()));
    const std::uint64_t jsonLength = le32(b, 12), jsonType = le32(b, 16);
    if (jsonType != kChunkJson) refuse(file, 0, "the glb's first chunk is not its JSON");
    if (jsonLength > length - 20)
        refuse(file, 0,
               "the glb's JSON chunk says " + std::to_string(jsonLength) + " bytes, the file has " +
                   std::to_string(length - 20) + " after its header");
    GlbParts parts;
    parts.json = b.substr(20, jsonLength);
    std::uint64_t at = 20 + jsonLength;
    at = (at + 3) & ~std::uint64_t(3);  // chunks start on 4 bytes
    if (at + 8 <= length) {
        const std::uint64_t binLength = le32(b, at), binType = le32(b, at + 4);
        if (binType == kChunkBin) {
            if (binLength > length - at - 8)
                refuse(file, 0,
                       "the glb's binary chunk says " + std::to_string(binLength) +
                           " bytes, the file has " + std::to_string(length - at - 8) +
                           " after its start");
            parts.hasBin = true;
            parts.binBytes = binLength;
        }
    }
    return parts;
}

using Json = nlohmann::json;
using GltfReader = JsonReader<SceneError>;

class GltfCheck {
  public:
    GltfCheck(const std::string& file, const GltfReader& r, const Json& root, const GlbParts* glb,
              const FileSizer& sizeOf)
        : file_(file), r_(r), root_(root), glb_(glb), sizeOf_(sizeOf) {}

    std::vector<std::string> run() {
        r_.requireObject(root_, "");
        const Json* asset = member(root_, "", "asset");
        if (!asset || !asset->is_object() || !asset->contains("version") ||
            !(*asset)["version"].is_string())
            r_.fail("asset", "a glTF file names its version: \"asset\": {\"version\": \"2.0\"}");
        const std::string version = (*asset)["version"].get<std::string>();
        if (!version.starts_with("2."))
            r_.fail("asset.version",
                    "glTF version '" + printable(version, 16) + "': raystep reads glTF 2.0");
        buffers();
        bufferViews();
        accessors();
        meshes();
        nodes();
        images();
        animations();
        return external_;
    }

  private:
    const Json* member(const Json& j, const std::string& path, const char* key) const {
        (void)path;
        const auto it = j.find(key);
        return it == j.end() ? nullptr : &*it;
    }
    /// root[key] as an array (absent: empty), each element an object.
    const Json& list(const char* key) const {
        static const Json empty = Json::array();
        const Json* j = member(root_, "", key);
        if (!j) return empty;
        // Checked once: index() asks for its table at every reference (accessors x views).
        if (!listed_.insert(key).second) return *j;
        if (!j->is_array()) r_.fail(key, "expected an array, got " + GltfReader::typeName(*j));
        for (std::size_t i = 0; i < j->size(); ++i)
            r_.requireObject((*j)[i], JsonLineMap::element(key, i));
        return *j;
    }
    std::uint64_t whole(const Json& j, const std::string& path, std::uint64_t lo,
                        std::uint64_t hi) const {
        const double v = r_.number(j, path);
        if (v != std::floor(v) || v < double(lo) || v > double(hi))
            r_.fail(path, "expected a whole number from " + std::to_string(lo) + " to " +
                              std::to_string(hi) + ", got " + GltfReader::fmt(v));
        return static_cast<std::uint64_t>(v);
    }
    std::optional<std::uint64_t> optWhole(const Json& obj, const std::string& path, const char* key,
                                          std::uint64_t lo, std::uint64_t hi) const {
        const auto it = obj.find(key);
        if (it == obj.end()) return std::nullopt;
        return whole(*it, JsonLineMap::child(path, key), lo, hi);
    }
    /// An index into root[table].
    std::uint64_t index(const Json& obj, const std::string& path, const char* key,
                        const char* table) const {
        const Json& t = list(table);
        if (t.empty())
            r_.fail(JsonLineMap::child(path, key),
                    std::string("refers to ") + table + ", but the file has none");
        return whole(obj[key], JsonLineMap::child(path, key), 0, t.size() - 1);
    }

    void buffers() {
        const Json& b = list("buffers");
        std::uint64_t sum = 0;
        for (std::size_t i = 0; i < b.size(); ++i) {
            const std::string path = JsonLineMap::element("buffers", i);
            if (!b[i].contains("byteLength")) r_.fail(path, "a buffer needs its byteLength");
            const std::uint64_t length =
                whole(b[i]["byteLength"], JsonLineMap::child(path, "byteLength"), 1,
                      std::uint64_t(1) << 53);
            bufferBytes_.push_back(length);
            sum += length;
            // Every buffer is read whole, even when two name one file (40 naming one 100 MB .bin
            // took 3.9 GB): their sum is capped like one model file.
            if (sum > kMaxObjFileBytes)
                r_.fail(path, "the buffers add up to " + std::to_string(sum) +
                                  " bytes, more than the " +
                                  std::to_string(kMaxObjFileBytes >> 20) +
                                  " MB raystep reads for one model");
            const auto uri = b[i].find("uri");
            if (uri == b[i].end()) {
                if (!(glb_ && glb_->hasBin && i == 0))
                    r_.fail(path, glb_ ? "only the first buffer of a glb may be its binary chunk"
                                       : "a buffer of a .gltf file needs a uri");
                if (length > glb_->binBytes)
                    r_.fail(JsonLineMap::child(path, "byteLength"),
                            "says " + std::to_string(length) + " bytes, the glb's binary chunk " +
                                "holds " + std::to_string(glb_->binBytes));
                continue;
            }
            const std::string up = JsonLineMap::child(path, "uri");
            const std::string name = r_.string(*uri, up);
            if (name.starts_with("data:")) {
                // base64: 3 bytes in 4 characters.
                const std::size_t comma = name.find(',');
                const std::uint64_t encoded =
                    comma == std::string::npos ? 0 : (name.size() - comma - 1) / 4 * 3;
                if (length > encoded)
                    r_.fail(up, "a data: URI of " + std::to_string(encoded) +
                                    " bytes for a byteLength of " + std::to_string(length));
                continue;
            }
            const std::string resolved =
                (std::filesystem::path(file_).parent_path() / name).lexically_normal().string();
            std::uint64_t size = 0;
            try {
                size = sizeOf_(resolved);
            } catch (const ReadFailure& f) {
                r_.fail(up, "cannot read '" + printable(name) + "': " + f.what());
            }
            if (size < length)
                r_.fail(up, "'" + printable(name) + "' has " + std::to_string(size) +
                                " bytes, the buffer's byteLength says " + std::to_string(length));
            external_.push_back(resolved);
        }
    }

    void bufferViews() {
        const Json& v = list("bufferViews");
        for (std::size_t i = 0; i < v.size(); ++i) {
            const std::string path = JsonLineMap::element("bufferViews", i);
            if (!v[i].contains("buffer") || !v[i].contains("byteLength"))
                r_.fail(path, "a buffer view needs its buffer and byteLength");
            const std::uint64_t buffer = index(v[i], path, "buffer", "buffers");
            const std::uint64_t length =
                whole(v[i]["byteLength"], JsonLineMap::child(path, "byteLength"), 1,
                      bufferBytes_[buffer]);
            const std::uint64_t offset =
                optWhole(v[i], path, "byteOffset", 0, bufferBytes_[buffer]).value_or(0);
            if (offset + length > bufferBytes_[buffer])
                r_.fail(path, "bytes " + std::to_string(offset) + " to " +
                                  std::to_string(offset + length) + " of a buffer of " +
                                  std::to_string(bufferBytes_[buffer]));
            const std::uint64_t stride = optWhole(v[i], path, "byteStride", 4, 252).value_or(0);
            viewBytes_.push_back(length);
            viewStride_.push_back(stride);
        }
    }

    void accessors() {
        const Json& a = list("accessors");
        static const std::array<std::pair<const char*, int>, 7> types = {{{"SCALAR", 1},
                                                                          {"VEC2", 2},
                                                                          {"VEC3", 3},
                                                                          {"VEC4", 4},
                                                                          {"MAT2", 4},
                                                                          {"MAT3", 9},
                                                                          {"MAT4", 16}}};
        for (std::size_t i = 0; i < a.size(); ++i) {
            const std::string path = JsonLineMap::element("accessors", i);
            if (!a[i].contains("count") || !a[i].contains("componentType") ||
                !a[i].contains("type"))
                r_.fail(path, "an accessor needs its count, componentType and type");
            const std::uint64_t count =
                whole(a[i]["count"], JsonLineMap::child(path, "count"), 1, kMaxGltfElements);
            const std::uint64_t component =
                whole(a[i]["componentType"], JsonLineMap::child(path, "componentType"), 5120, 5126);
            if (component == 5124)
                r_.fail(JsonLineMap::child(path, "componentType"), "5124 is no component type");
            const std::string type = r_.string(a[i]["type"], JsonLineMap::child(path, "type"));
            int components = 0;
            for (const auto& [name, n] : types)
                if (type == name) components = n;
            if (components == 0)
                r_.fail(JsonLineMap::child(path, "type"),
                        "unknown type '" + printable(type, 16) +
                            "' (SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3, MAT4)");
            const std::uint64_t size = components * (component <= 5121   ? 1u
                                                     : component <= 5123 ? 2u
                                                                         : 4u);
            if (a[i].contains("bufferView")) {
                const std::uint64_t view = index(a[i], path, "bufferView", "bufferViews");
                const std::uint64_t offset =
                    optWhole(a[i], path, "byteOffset", 0, viewBytes_[view]).value_or(0);
                const std::uint64_t stride = viewStride_[view] ? viewStride_[view] : size;
                if (offset + (count - 1) * stride + size > viewBytes_[view])
                    r_.fail(path, std::to_string(count) + " elements of " + std::to_string(size) +
                                      " bytes do not fit buffer view " + std::to_string(view) +
                                      " (" + std::to_string(viewBytes_[view]) + " bytes)");
            } else if (count * size > kMaxObjFileBytes)
                // No buffer view: zeros, made by assimp in memory.
                r_.fail(path, std::to_string(count) + " elements of " + std::to_string(size) +
                                  " bytes without a buffer view, more than " +
                                  std::to_string(kMaxObjFileBytes >> 20) + " MB");
            if (const auto sparse = a[i].find("sparse"); sparse != a[i].end()) {
                const std::string sp = JsonLineMap::child(path, "sparse");
                r_.requireObject(*sparse, sp);
                if (!sparse->contains("count")) r_.fail(sp, "a sparse accessor needs its count");
                const std::uint64_t n =
                    whole((*sparse)["count"], JsonLineMap::child(sp, "count"), 1, count);
                for (const char* part : {"indices", "values"}) {
                    const std::string pp = JsonLineMap::child(sp, part);
                    const auto it = sparse->find(part);
                    if (it == sparse->end() || !it->is_object() || !it->contains("bufferView"))
                        r_.fail(pp, "needs its bufferView");
                    const std::uint64_t view = index(*it, pp, "bufferView", "bufferViews");
                    const std::uint64_t offset =
                        optWhole(*it, pp, "byteOffset", 0, viewBytes_[view]).value_or(0);
                    // The indices' own type: unsigned bytes, shorts or ints (5121, 5123, 5125).
                    std::uint64_t each = size;
                    if (std::string_view(part) == "indices") {
                        const std::string cp = JsonLineMap::child(pp, "componentType");
                        if (!it->contains("componentType"))
                            r_.fail(pp, "sparse indices need their componentType");
                        const std::uint64_t type = whole((*it)["componentType"], cp, 5121, 5125);
                        if (type != 5121 && type != 5123 && type != 5125)
                            r_.fail(cp, "sparse indices are unsigned: 5121, 5123 or 5125, got " +
                                            std::to_string(type));
                        each = type == 5121 ? 1 : type == 5123 ? 2 : 4;
                    }
                    if (offset + n * each > viewBytes_[view])
                        r_.fail(pp, std::to_string(n) + " sparse elements do not fit buffer view " +
                                        std::to_string(view));
                }
            }
            counts_.push_back(count);
            components_.push_back(components);
            componentTypes_.push_back(component);
        }
    }

    /// Adds an accessor's elements to what assimp will copy, under the cap.
    void copied(std::uint64_t accessor, const std::string& path) {
        elements_ += counts_[accessor];
        if (elements_ > kMaxGltfElements)
            r_.fail(path, "the model's primitives and animations read more than " +
                              std::to_string(kMaxGltfElements) +
                              " accessor elements (each primitive copies its own)");
    }

    void meshes() {
        const Json& m = list("meshes");
        std::uint64_t triangles = 0;
        for (std::size_t i = 0; i < m.size(); ++i) {
            const std::string path = JsonLineMap::element("meshes", i);
            const auto prims = m[i].find("primitives");
            if (prims == m[i].end() || !prims->is_array() || prims->empty())
                r_.fail(path, "a mesh needs an array of primitives");
            MeshCost cost;
            for (std::size_t k = 0; k < prims->size(); ++k) {
                const Json& p = (*prims)[k];
                const std::string pp =
                    JsonLineMap::element(JsonLineMap::child(path, "primitives"), k);
                r_.requireObject(p, pp);
                const auto attrs = p.find("attributes");
                const std::string ap = JsonLineMap::child(pp, "attributes");
                if (attrs == p.end() || !attrs->is_object())
                    r_.fail(ap, "a primitive needs its attributes");
                // A strip or fan without positions made assimp count 2^32 - 2 faces (64 GB).
                if (!attrs->contains("POSITION"))
                    r_.fail(ap, "no POSITION attribute: raystep needs the vertices' positions");
                for (const auto& [name, value] : attrs->items()) {
                    const std::uint64_t a = whole(value, JsonLineMap::child(ap, name), 0,
                                                  counts_.empty() ? 0 : counts_.size() - 1);
                    if (counts_.empty())
                        r_.fail(JsonLineMap::child(ap, name), "the file has no accessors");
                    copied(a, JsonLineMap::child(ap, name));
                }
                const std::uint64_t position = (*attrs)["POSITION"].get<std::uint64_t>();
                if (components_[position] != 3 || componentTypes_[position] != 5126)
                    r_.fail(JsonLineMap::child(ap, "POSITION"),
                            "positions are VEC3 of floats (componentType 5126)");
                std::uint64_t corners = counts_[position];
                if (p.contains("indices")) {
                    const std::uint64_t ix = index(p, pp, "indices", "accessors");
                    if (components_[ix] != 1 || componentTypes_[ix] == 5126 ||
                        componentTypes_[ix] == 5120 || componentTypes_[ix] == 5122)
                        r_.fail(JsonLineMap::child(pp, "indices"),
                                "indices are SCALAR unsigned integers");
                    copied(ix, JsonLineMap::child(pp, "indices"));
                    corners = counts_[ix];
                }
                if (const auto targets = p.find("targets"); targets != p.end()) {
                    if (!targets->is_array())
                        r_.fail(JsonLineMap::child(pp, "targets"), "expected an array");
                    for (std::size_t t = 0; t < targets->size(); ++t) {
                        const std::string tp =
                            JsonLineMap::element(JsonLineMap::child(pp, "targets"), t);
                        r_.requireObject((*targets)[t], tp);
                        for (const auto& [name, value] : (*targets)[t].items()) {
                            if (counts_.empty())
                                r_.fail(JsonLineMap::child(tp, name), "the file has no accessors");
                            const std::uint64_t a =
                                whole(value, JsonLineMap::child(tp, name), 0, counts_.size() - 1);
                            copied(a, JsonLineMap::child(tp, name));
                        }
                    }
                }
                const std::uint64_t mode = optWhole(p, pp, "mode", 0, 6).value_or(4);
                const std::uint64_t tris = mode == 4   ? corners / 3
                                           : mode >= 5 ? (corners >= 2 ? corners - 2 : 0)
                                                       : 0;
                cost.vertices += counts_[position];
                cost.triangles += tris;
                cost.other += mode < 4 ? corners : 0;
                triangles += tris;
                if (triangles > kMaxModelTriangles)
                    r_.fail(pp, "the model's meshes hold more than " +
                                    std::to_string(kMaxModelTriangles) +
                                    " triangles, the most raystep reads from one model");
            }
            meshCost_.push_back(cost);
        }
    }

    void nodes() {
        const Json& n = list("nodes");
        if (n.size() > kMaxGltfNodes)
            r_.fail("nodes", "more than " + std::to_string(kMaxGltfNodes) + " nodes");
        std::vector<std::int64_t> parent(n.size(), -1);
        for (std::size_t i = 0; i < n.size(); ++i) {
            const std::string path = JsonLineMap::element("nodes", i);
            if (n[i].contains("mesh")) index(n[i], path, "mesh", "meshes");
            const auto children = n[i].find("children");
            if (children == n[i].end()) continue;
            const std::string cp = JsonLineMap::child(path, "children");
            if (!children->is_array()) r_.fail(cp, "expected an array of node indices");
            for (std::size_t k = 0; k < children->size(); ++k) {
                const std::string kp = JsonLineMap::element(cp, k);
                const std::uint64_t c = whole((*children)[k], kp, 0, n.size() - 1);
                // A node listed twice (by one parent or two) is a second copy of its subtree
                // in assimp: each level of such a chain doubled the memory.
                if (parent[c] >= 0 || c == i)
                    r_.fail(kp, "node " + std::to_string(c) +
                                    " has a second parent here (glTF nodes form trees)");
                parent[c] = std::int64_t(i);
            }
        }
        // Every tree's depth, scene or not (assimp reads a skin's joints and an animation's
        // targets with their subtrees, recursively), without recursion here; a node never
        // reached from a node without a parent is in a cycle (each has one parent at most).
        {
            std::vector<std::pair<std::uint64_t, int>> stack;
            std::vector<bool> reached(n.size(), false);
            for (std::size_t i = 0; i < n.size(); ++i)
                if (parent[i] < 0) stack.emplace_back(i, 1);
            while (!stack.empty()) {
                const auto [i, depth] = stack.back();
                stack.pop_back();
                reached[i] = true;
                if (depth > kMaxGltfNodeDepth)
                    r_.fail(JsonLineMap::element("nodes", i),
                            "the node tree is deeper than " + std::to_string(kMaxGltfNodeDepth) +
                                " levels");
                if (const auto children = n[i].find("children"); children != n[i].end())
                    for (const Json& c : *children)
                        stack.emplace_back(c.get<std::uint64_t>(), depth + 1);
            }
            for (std::size_t i = 0; i < n.size(); ++i)
                if (!reached[i])
                    r_.fail(JsonLineMap::element("nodes", i),
                            "node " + std::to_string(i) + " is its own ancestor (a cycle)");
        }
        // The scene assimp imports: "scene", else the first; its nodes, each once.
        const Json& scenes = list("scenes");
        std::vector<std::uint64_t> roots;
        if (!scenes.empty()) {
            const std::uint64_t s =
                root_.contains("scene") ? index(root_, "", "scene", "scenes") : 0;
            const std::string sp = JsonLineMap::element("scenes", s);
            if (const auto list = scenes[s].find("nodes"); list != scenes[s].end()) {
                if (!list->is_array())
                    r_.fail(JsonLineMap::child(sp, "nodes"), "expected an array of node indices");
                std::set<std::uint64_t> seen;
                for (std::size_t k = 0; k < list->size(); ++k) {
                    const std::string kp = JsonLineMap::element(JsonLineMap::child(sp, "nodes"), k);
                    const std::uint64_t r = whole((*list)[k], kp, 0, n.empty() ? 0 : n.size() - 1);
                    if (n.empty()) r_.fail(kp, "the file has no nodes");
                    if (!seen.insert(r).second || parent[r] >= 0)
                        r_.fail(kp, "node " + std::to_string(r) +
                                        " is listed twice (a scene's nodes are roots, each once)");
                    roots.push_back(r);
                }
            }
        } else {
            for (std::size_t i = 0; i < n.size(); ++i)
                if (parent[i] < 0) roots.push_back(i);
        }
        // Depth first without recursion: depth, cycles (a node above itself never reaches a
        // root), and what the instances cost the walk after assimp.
        std::vector<std::pair<std::uint64_t, int>> stack;
        for (const std::uint64_t r : roots) stack.emplace_back(r, 1);
        std::uint64_t triangles = 0, vertices = 0, other = 0;
        while (!stack.empty()) {
            const auto [i, depth] = stack.back();
            stack.pop_back();
            const std::string path = JsonLineMap::element("nodes", i);
            (void)depth;
            if (n[i].contains("mesh")) {
                const MeshCost& c = meshCost_[n[i]["mesh"].get<std::uint64_t>()];
                triangles += c.triangles;
                vertices += c.vertices;
                other += c.other;
                if (triangles > kMaxModelTriangles || vertices > kMaxModelVertices ||
                    other > kMaxModelPointsAndLines)
                    r_.fail(path, "the model's nodes place more than " +
                                      std::to_string(kMaxModelTriangles) + " triangles, " +
                                      std::to_string(kMaxModelVertices) + " vertices or " +
                                      std::to_string(kMaxModelPointsAndLines) +
                                      " points and lines (a mesh counts once a node using it)");
            }
            if (const auto children = n[i].find("children"); children != n[i].end())
                for (const Json& c : *children)
                    stack.emplace_back(c.get<std::uint64_t>(), depth + 1);
        }
    }

    void images() {
        const Json& im = list("images");
        std::uint64_t sum = 0;
        for (std::size_t i = 0; i < im.size(); ++i) {
            const std::string path = JsonLineMap::element("images", i);
            if (!im[i].contains("bufferView")) continue;
            const std::uint64_t view = index(im[i], path, "bufferView", "bufferViews");
            // Each image copies its bytes out of the buffer: many naming one big view add up.
            sum += viewBytes_[view];
            if (sum > kMaxObjFileBytes)
                r_.fail(path, "the images add up to more than " +
                                  std::to_string(kMaxObjFileBytes >> 20) + " MB");
        }
    }

    void animations() {
        const Json& an = list("animations");
        for (std::size_t i = 0; i < an.size(); ++i) {
            const std::string path = JsonLineMap::element("animations", i);
            const auto samplers = an[i].find("samplers");
            if (samplers == an[i].end()) continue;
            const std::string sp = JsonLineMap::child(path, "samplers");
            if (!samplers->is_array()) r_.fail(sp, "expected an array");
            for (std::size_t k = 0; k < samplers->size(); ++k) {
                const std::string kp = JsonLineMap::element(sp, k);
                r_.requireObject((*samplers)[k], kp);
                for (const char* part : {"input", "output"})
                    if ((*samplers)[k].contains(part))
                        copied(index((*samplers)[k], kp, part, "accessors"),
                               JsonLineMap::child(kp, part));
            }
        }
    }

    struct MeshCost {
        std::uint64_t vertices = 0, triangles = 0, other = 0;
    };

    const std::string& file_;
    const GltfReader& r_;
    const Json& root_;
    const GlbParts* glb_;
    const FileSizer& sizeOf_;
    std::vector<std::uint64_t> bufferBytes_, viewBytes_, viewStride_, counts_, componentTypes_;
    std::vector<int> components_;
    std::vector<MeshCost> meshCost_;
    mutable std::set<std::string> listed_;  ///< the tables list() has checked
    std::uint64_t elements_ = 0;
    std::vector<std::string> external_;
};

}  // namespace

std::vector<std::string> checkGltf(const std::string& file, std::string_view bytes,
                                   const FileSizer& sizeOf) {
    std::optional<GlbParts> glb;
    if (bytes.size() >= 4 && le32(bytes, 0) == kGlbMagic) glb = splitGlb(file, bytes);
    auto parsed = parseJsonFile<SceneError>(glb ? glb->json : bytes, file, /*comments=*/false);
    const GltfReader r(file, std::move(parsed.lines));
    return guarded<SceneError>(
        file, [&] { return GltfCheck(file, r, parsed.root, glb ? &*glb : nullptr, sizeOf).run(); });
}

ModelChecked checkModelBytes(const std::string& path, std::string_view bytes,
                             const FileSizer& sizeOf) {
    const std::string ext = extensionOf(path);
    ModelChecked checked;
    if (ext == ".ply") checkPly(path, bytes);
    if (ext == ".stl") checkStl(path, bytes);
    if (ext == ".obj") checkObj(path, bytes);
    if (ext == ".gltf" || ext == ".glb") checked.buffers = checkGltf(path, bytes, sizeOf);
    return checked;
}

std::vector<std::string> modelReferences(const std::string& path, std::string_view bytes) {
    const std::string ext = extensionOf(path);
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    std::vector<std::string> out;
    const auto add = [&](std::string_view name, const std::filesystem::path& from) {
        if (!name.empty() && !name.starts_with("data:"))
            out.push_back((from / std::string(name)).lexically_normal().string());
    };
    if (ext == ".obj") {
        // mtllib NAME...: assimp takes the rest of the line as one name; either way, listed.
        std::vector<std::string> libraries;
        std::size_t pos = 0;
        while (pos < bytes.size() && out.size() < 1000) {
            std::size_t end = bytes.find_first_of("\n\r", pos);
            if (end == std::string_view::npos) end = bytes.size();
            const std::string_view line = bytes.substr(pos, end - pos);
            pos = end + 1;
            if (!line.starts_with("mtllib")) continue;
            const auto w = objFields(line.substr(6));
            for (const auto name : w) add(name, folder);
            if (w.size() > 1) {
                const std::size_t from = w.front().data() - line.data();
                add(line.substr(from, w.back().data() + w.back().size() - line.data() - from),
                    folder);
            }
        }
        // The textures a library names (map_Kd tex.png ...: the last word of the statement).
        const std::vector<std::string> mtls = out;
        for (const std::string& mtl : mtls) {
            std::string text;
            try {
                text = readRegularFile(mtl, kMaxJsonFileBytes);
            } catch (const ReadFailure&) {
                continue;
            }
            std::size_t at = 0;
            while (at < text.size() && out.size() < 1000) {
                std::size_t end = text.find_first_of("\n\r", at);
                if (end == std::string::npos) end = text.size();
                const auto w = words(std::string_view(text).substr(at, end - at));
                at = end + 1;
                if (w.size() >= 2 && (w[0].starts_with("map_") || w[0] == "bump" ||
                                      w[0] == "disp" || w[0] == "decal" || w[0] == "refl"))
                    add(w.back(), std::filesystem::path(mtl).parent_path());
            }
        }
    } else if (ext == ".gltf" || ext == ".glb") {
        try {
            std::string_view json = bytes;
            if (bytes.size() >= 4 && le32(bytes, 0) == kGlbMagic) json = splitGlb(path, bytes).json;
            if (JsonLineMap::tooDeepLine(json)) return out;
            const Json root = Json::parse(json.begin(), json.end(), nullptr, false);
            if (!root.is_object()) return out;
            for (const char* table : {"buffers", "images"})
                if (const auto t = root.find(table); t != root.end() && t->is_array())
                    for (const Json& e : *t)
                        if (e.is_object() && e.contains("uri") && e["uri"].is_string())
                            add(e["uri"].get<std::string>(), folder);
        } catch (const std::exception&) {
        }
    }
    return out;
}

}  // namespace raystep::detail

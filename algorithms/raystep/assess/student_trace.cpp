#include "raystep/assess/student_trace.h"

#include "raystep/base/json_reader.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <limits>

namespace raystep {

namespace {

using nlohmann::json;

constexpr std::size_t kMaxStudentTraceBytes = std::size_t(256) << 20;

struct LineReader {
    const std::string& file;
    int line;
    [[noreturn]] void fail(const std::string& key, const std::string& message) const {
        throw FileError(file, line, key, message);
    }
    std::array<double, 3> numbers(const json& j, const std::string& key, int dims) const {
        if (!j.is_array() || int(j.size()) != dims)
            fail(key, "expected " + std::to_string(dims) + " numbers [" +
                          (dims == 2 ? "x, y" : "x, y, z") + "], got " + j.dump(-1, ' ', true));
        std::array<double, 3> v{};
        for (int i = 0; i < dims; ++i) {
            if (!j[i].is_number()) fail(key, "expected a number, got " + j[i].dump(-1, ' ', true));
            v[i] = j[i].get<double>();
            if (!std::isfinite(v[i])) fail(key, "the number is too large for a double");
        }
        return v;
    }
    long long whole(const json& j, const std::string& key, long long lo, long long hi) const {
        if (!j.is_number_integer())
            fail(key, "expected a whole number, got " + j.dump(-1, ' ', true));
        const long long v = j.is_number_unsigned() && j.get<std::uint64_t>() > std::uint64_t(hi)
                                ? hi + 1
                                : j.get<long long>();
        if (v < lo || v > hi)
            fail(key, "expected a whole number from " + std::to_string(lo) + " to " +
                          std::to_string(hi) + ", got " + j.dump());
        return v;
    }
    void onlyKeys(const json& j, const std::string& path,
                  std::initializer_list<const char*> allowed) const {
        for (const auto& [k, v] : j.items()) {
            bool ok = false;
            for (const char* a : allowed) ok = ok || k == a;
            if (!ok)
                fail(path.empty() ? k : path + "." + k,
                     "unknown key (expected " + detail::joinNames(allowed) + ")");
        }
    }
};

/// A bare Infinity, -Infinity or NaN outside strings: what Python's json.dumps writes for inf.
bool hasNonJsonNumber(std::string_view s) {
    bool inString = false;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (s.substr(i, 8) == "Infinity" || s.substr(i, 3) == "NaN") {
            return true;
        }
    }
    return false;
}

/// `line` with each bare -0 written -0.0: JSON's integer -0 reads as 0 and would lose the sign
/// that C's printf("%g", -0.0) gives, and the negative-zero mistake is told by it.
std::string keepNegativeZero(std::string_view line) {
    std::string out;
    bool inString = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        out += c;
        if (inString) {
            if (c == '\\' && i + 1 < line.size())
                out += line[++i];
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '-' && i + 1 < line.size() && line[i + 1] == '0') {
            const char after = i + 2 < line.size() ? line[i + 2] : ' ';
            if (!(std::isdigit(static_cast<unsigned char>(after)) || after == '.' || after == 'e' ||
                  after == 'E')) {
                out += "0.0";
                ++i;
            }
        }
    }
    return out;
}

}  // namespace

StudentTrace readStudentTrace(std::string_view text, const std::string& file, int dims) {
    StudentTrace trace;
    trace.file = file;
    int lineNo = 0;
    constexpr long long kMaxId = std::numeric_limits<std::uint32_t>::max() - 1;
    constexpr long long kMaxCell = std::numeric_limits<int>::max();
    for (std::size_t at = 0, end = 0; at <= text.size(); at = end + 1) {
        end = std::min(text.find('\n', at), text.size());
        std::string_view line = text.substr(at, end - at);
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (lineNo == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
        if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
        const LineReader r{file, lineNo};
        if (JsonLineMap::tooDeepLine(line, 8)) r.fail("", "nested too deep for a trace record");
        json j;
        try {
            j = json::parse(keepNegativeZero(line));
        } catch (const json::parse_error& e) {
            if (hasNonJsonNumber(line))
                r.fail("",
                       "Infinity and NaN are not JSON numbers: write null for an infinite tMax "
                       "(Python: None)");
            r.fail("", std::string("not a JSON object: ") + e.what());
        } catch (const json::exception&) {
            // nlohmann's out_of_range: a number beyond double's range (5e308).
            r.fail("", "a number too large for a double");
        }
        if (!j.is_object() || j.size() == 0)
            r.fail("",
                   "expected one record {\"ray\": ...}, {\"cell\": ...}, {\"test\": ...}, "
                   "{\"node\": ...}, {\"hit\": ...} or {\"miss\": true}");
        if (j.contains("ray")) {
            r.onlyKeys(j, "", {"ray"});
            const json& ray = j["ray"];
            if (!ray.is_object()) r.fail("ray", "expected {\"origin\": [..], \"dir\": [..]}");
            r.onlyKeys(ray, "ray", {"origin", "dir"});
            if (!ray.contains("origin")) r.fail("ray.origin", "missing");
            if (!ray.contains("dir")) r.fail("ray.dir", "missing");
            StudentRay sr;
            sr.line = lineNo;
            sr.dims = dims;
            sr.origin = r.numbers(ray["origin"], "ray.origin", dims);
            sr.dir = r.numbers(ray["dir"], "ray.dir", dims);
            bool zero = true;
            for (int i = 0; i < dims; ++i) zero = zero && sr.dir[i] == 0.0;
            if (zero) r.fail("ray.dir", "the direction is zero: the ray goes nowhere");
            trace.rays.push_back(sr);
            continue;
        }
        if (trace.rays.empty())
            r.fail(j.begin().key(),
                   "a record before the first {\"ray\": ...}: which ray is it of?");
        StudentRecord rec;
        rec.line = lineNo;
        if (j.contains("cell")) {
            r.onlyKeys(j, "", {"cell", "tMax"});
            const json& c = j["cell"];
            if (!c.is_array() || int(c.size()) != dims)
                r.fail("cell", "expected " + std::to_string(dims) + " whole numbers [" +
                                   (dims == 2 ? "i, j" : "i, j, k") + "]");
            rec.kind = StudentRecordKind::Cell;
            for (int i = 0; i < dims; ++i)
                rec.cell[i] = r.whole(c[i], "cell[" + std::to_string(i) + "]", -kMaxCell, kMaxCell);
            if (j.contains("tMax")) {
                const json& m = j["tMax"];
                if (!m.is_array() || int(m.size()) != dims)
                    r.fail("tMax", "expected " + std::to_string(dims) +
                                       " numbers (null for an axis the ray is parallel to)");
                std::array<double, 3> v{};
                for (int i = 0; i < dims; ++i) {
                    const std::string key = "tMax[" + std::to_string(i) + "]";
                    if (m[i].is_null()) {
                        v[i] = std::numeric_limits<double>::infinity();
                    } else if (m[i].is_number()) {
                        v[i] = m[i].get<double>();
                        if (!std::isfinite(v[i]))
                            r.fail(key, "the number is too large for a double");
                    } else {
                        r.fail(key, "expected a number or null, got " + m[i].dump(-1, ' ', true));
                    }
                }
                rec.tMax = v;
            }
        } else if (j.contains("test")) {
            r.onlyKeys(j, "", {"test"});
            rec.kind = StudentRecordKind::Test;
            rec.id = static_cast<std::uint32_t>(r.whole(j["test"], "test", 0, kMaxId));
        } else if (j.contains("node")) {
            r.onlyKeys(j, "", {"node"});
            rec.kind = StudentRecordKind::Node;
            rec.id = static_cast<std::uint32_t>(r.whole(j["node"], "node", 0, kMaxId));
        } else if (j.contains("hit")) {
            r.onlyKeys(j, "", {"hit"});
            const json& h = j["hit"];
            if (!h.is_object()) r.fail("hit", "expected {\"prim\": P, \"t\": T}");
            r.onlyKeys(h, "hit", {"prim", "t"});
            if (!h.contains("prim")) r.fail("hit.prim", "missing");
            if (!h.contains("t")) r.fail("hit.t", "missing");
            rec.kind = StudentRecordKind::Hit;
            rec.id = static_cast<std::uint32_t>(r.whole(h["prim"], "hit.prim", 0, kMaxId));
            if (!h["t"].is_number()) r.fail("hit.t", "expected a number");
            rec.t = h["t"].get<double>();
            if (!std::isfinite(rec.t)) r.fail("hit.t", "the number is too large for a double");
        } else if (j.contains("miss")) {
            r.onlyKeys(j, "", {"miss"});
            if (j["miss"] != true) r.fail("miss", "expected true");
            rec.kind = StudentRecordKind::Miss;
        } else {
            r.fail(j.begin().key(), "unknown record (expected ray, cell, test, node, hit or miss)");
        }
        StudentRay& ray = trace.rays.back();
        if (!ray.records.empty() && (ray.records.back().kind == StudentRecordKind::Hit ||
                                     ray.records.back().kind == StudentRecordKind::Miss))
            r.fail(j.begin().key(), "a record after this ray's hit or miss (line " +
                                        std::to_string(ray.records.back().line) +
                                        "): start the next ray with {\"ray\": ...}");
        ray.records.push_back(rec);
    }
    if (trace.rays.empty())
        throw FileError(file, 0, "", "no ray: the trace has no {\"ray\": ...} line");
    return trace;
}

StudentTrace loadStudentTrace(const std::string& path, int dims) {
    std::string text;
    try {
        text = detail::readRegularFile(path, kMaxStudentTraceBytes);
    } catch (const detail::ReadFailure& e) {
        throw FileError(path, 0, "", e.what());
    }
    return readStudentTrace(text, path, dims);
}

}  // namespace raystep

// What the exercise kinds share: reading a typed number, the tolerance check, the exercise's
// place in its trace, and the slips of a root that more than one kind grades.
#include "course/exercises/kind_unit.h"

#include "raystep/base/i18n.h"
#include "raystep/base/math.h"
#include "raystep/trace/event_text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace raystep::exercises {

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

std::optional<double> parseNumber(std::string_view s) {
    s = trim(s);
    if (s.empty()) return std::nullopt;
    std::string copy(s);
    // Any language's decimal mark, whatever the app's ("0,75" as Italian students write it).
    for (const Language lang : languages()) {
        const std::string_view mark = decimalMark(lang);
        if (mark == "." || mark.empty()) continue;
        for (std::size_t at = copy.find(mark); at != std::string::npos; at = copy.find(mark, at))
            copy.replace(at, mark.size(), ".");
    }
    double v = 0.0;
    const auto [end, ec] = std::from_chars(copy.data(), copy.data() + copy.size(), v);
    if (ec != std::errc() || end != copy.data() + copy.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::optional<long> parseWhole(std::string_view s) {
    const auto v = parseNumber(s);
    if (!v || *v != std::floor(*v) || std::abs(*v) > 1e9) return std::nullopt;
    return static_cast<long>(*v);
}

std::vector<std::string_view> splitAny(std::string_view s, std::string_view seps) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= s.size(); ++i)
        if (i == s.size() || seps.find(s[i]) != std::string_view::npos) {
            if (i > start) parts.push_back(s.substr(start, i - start));
            start = i + 1;
        }
    return parts;
}

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::optional<Answer> rejected(std::string* why, const std::string& message) {
    if (why) *why = message;
    return std::nullopt;
}

std::optional<Answer> parseOneNumber(std::string_view text, std::string* why, Language lang) {
    const auto v = parseNumber(text);
    if (!v) return rejected(why, tr(lang, "expected a number"));
    Answer a;
    a.numbers.push_back(*v);
    return a;
}

bool close(double answer, double reference, double tolerance) {
    return std::abs(answer - reference) <= tolerance * std::max(1.0, std::abs(reference));
}

std::string letter(int i) {
    return std::string(1, static_cast<char>('a' + i));
}

std::string whole(double v) {
    return std::to_string(static_cast<long long>(v));
}

std::string wholes(const std::vector<double>& numbers) {
    std::string s;
    // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on "," + to_string here.
    for (std::size_t i = 0; i < numbers.size(); ++i) {
        if (i) s += ',';
        s += whole(numbers[i]);
    }
    return s;
}

Context contextOf(const Exercise& ex, const EventLog& log, const std::string& file,
                  const std::vector<GridSweepRow>* sweep) {
    Context c{ex, log, file, 0, sweep};
    const auto at = resolvePosition(ex.at, log);
    if (!at) c.fail("its position (" + describePosition(ex.at) + ") is not in the trace");
    c.at = *at;
    return c;
}

/// The end of a count's or sequence's range.
std::size_t rangeEnd(const Context& c) {
    if (!c.ex.until) return c.log.events().size();
    const auto u = resolvePosition(*c.ex.until, c.log);
    if (!u || *u < c.at)
        c.fail("its end (" + describePosition(*c.ex.until) +
               ") is not in the trace after its start");
    return *u;
}

/// The near and far roots of ray `ray` against primitive `prim` when it is a circle or a sphere
/// of the scene (a = d.d, b = (o - c).d, c' = |o - c|^2 - r^2, t = (-b -+ sqrt(b^2 - a c')) / a).
namespace {
std::optional<std::pair<double, double>> roundRoots(const Context& c, std::uint32_t ray,
                                                    std::uint32_t prim) {
    if (!c.scene || ray >= c.log.rays().size()) return std::nullopt;
    const RayRecord& r = c.log.rays()[ray];
    Vec3 center{0.0};
    double radius = 0.0;
    if (const auto* s2 = std::get_if<Scene2D>(c.scene); s2 && s2->isCircle(prim)) {
        center = Vec3(s2->circles[prim].center.x, s2->circles[prim].center.y, 0.0);
        radius = s2->circles[prim].radius;
    } else if (const auto* s3 = std::get_if<Scene>(c.scene); s3 && s3->isSphere(prim)) {
        center = s3->spheres[prim].center;
        radius = s3->spheres[prim].radius;
    } else {
        return std::nullopt;
    }
    const Vec3 oc = r.origin - center;
    const double a = glm::dot(r.dir, r.dir), b = glm::dot(oc, r.dir);
    const double disc = b * b - a * (glm::dot(oc, oc) - radius * radius);
    if (!(a > 0.0) || disc < 0.0) return std::nullopt;
    return std::pair{(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a};
}

}  // namespace

/// The slip a wrong t of a hit betrays: the far root of a circle or sphere (with the scene), or
/// the root halved or doubled by a missing or extra division.
std::string rootSlip(const Context& c, double given, double right, std::uint32_t ray,
                     std::uint32_t prim, Language lang) {
    const auto n = [&](double v) { return formatNumber(v, lang); };
    const auto near = [&](double v) { return close(given, v, c.ex.tolerance); };
    if (const auto roots = roundRoots(c, ray, prim);
        roots && !near(right) && near(roots->second) && roots->second != right) {
        if (std::holds_alternative<Scene2D>(*c.scene))
            return trf(lang,
                       "%1 is the far root, where the ray leaves the circle: the intersection is "
                       "the near one.",
                       {n(given)});
        return trf(lang,
                   "%1 is the far root, where the ray leaves the sphere: the intersection is the "
                   "near one.",
                   {n(given)});
    }
    if (right == 0.0) return "";
    if (near(right / 2))
        return trf(lang,
                   "%1 is half the root: one division by 2 too many. The root is (−B − √(B² − "
                   "4AC)) / 2A, or with the half-b form, b = B/2, (−b − √(b² − AC)) / A.",
                   {n(given)});
    if (near(2 * right))
        return trf(lang,
                   "%1 is twice the root: the root (−B − √(B² − 4AC)) / 2A divides by 2A (the "
                   "slide leaves out /2A); with the half-b form, b = B/2, it divides by A alone.",
                   {n(given)});
    return "";
}

std::string stepTheReplayAdvice(Language lang) {
    return tr(lang, "Step the replay and look at the inspector.");
}

bool heldAtTheStart(const Exercise& ex) {
    return ex.at.mode == ReplayPosition::Mode::Start ||
           (ex.at.mode == ReplayPosition::Mode::Cursor && ex.at.cursor == 0);
}

void addLeakNumber(AnswerForms& f, double v) {
    // Whole 0 and 1 are in every formula.
    if (!(v == std::floor(v) && std::abs(v) <= 1.0)) f.numbers.push_back(v);
}

void addLeakCells(AnswerForms& f, const Answer& a, int per) {
    f.dims = per;
    for (std::size_t k = 0; per > 0 && k + per <= a.numbers.size(); k += per) {
        std::array<int, 3> c{0, 0, 0};
        for (int i = 0; i < per; ++i) c[i] = static_cast<int>(a.numbers[k + i]);
        f.cells.push_back(c);
    }
}

}  // namespace raystep::exercises

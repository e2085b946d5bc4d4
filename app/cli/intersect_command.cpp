// `raystep-cli intersect`: one kernel run on the parsed ray and shape, its range watched.
#include "intersect_command.h"

#include "common.h"

#include "raystep/base/format.h"
#include "raystep/geometry/kernels.h"

#include <nlohmann/json.hpp>

#include <cfenv>
#include <cstdio>
#include <iostream>

namespace raystep::cli {

void addIntersectCommand(CLI::App& app, IntersectArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "intersect", "Intersect one ray with one triangle or sphere and show the working");
    cmd->add_option("--ray", a.ray, "Ray as ox,oy,oz:dx,dy,dz")->required();
    auto* tri = cmd->add_option("--triangle", a.triangle, "Triangle as ax,ay,az:bx,by,bz:cx,cy,cz");
    auto* sph = cmd->add_option("--sphere", a.sphere, "Sphere as cx,cy,cz:r");
    tri->excludes(sph);
    cmd->add_option("--method", a.method,
                    "Triangle: plane, moller-trumbore, watertight (default); "
                    "sphere: textbook, stable (default)");
    cmd->add_option("--precision", a.precision, "float or double")->capture_default_str();
    cmd->add_flag("--json", a.json, "Print the result as JSON");
}

namespace {

/// "p0:p1:..." with `groups` groups of `sizes[i]` finite numbers each.
std::optional<std::vector<std::vector<double>>> parseGroups(const std::string& text,
                                                            const std::vector<int>& sizes) {
    std::vector<std::vector<double>> groups;
    std::size_t start = 0;
    for (std::size_t g = 0; g < sizes.size(); ++g) {
        const std::size_t end = text.find(':', start);
        const bool last = g + 1 == sizes.size();
        if (last != (end == std::string::npos)) return std::nullopt;
        const auto numbers =
            parseNumbers(text.substr(start, last ? std::string::npos : end - start));
        if (!numbers || static_cast<int>(numbers->size()) != sizes[g]) return std::nullopt;
        groups.push_back(*numbers);
        start = end + 1;
    }
    return groups;
}

glm::dvec3 vec(const std::vector<double>& v) {
    return {v[0], v[1], v[2]};
}

/// Every digit of a number in the precision it was computed in, so the working can be checked to
/// the last bit.
std::string allDigits(double v, bool isFloat) {
    return isFloat ? formatNumber(float(v), kRoundTripDigits<float>)
                   : formatNumber(v, kRoundTripDigits<double>);
}
std::string allDigits(const glm::dvec3& v, bool isFloat) {
    return "(" + allDigits(v.x, isFloat) + ", " + allDigits(v.y, isFloat) + ", " +
           allDigits(v.z, isFloat) + ")";
}
std::string stepText(const StepLog::Step& s, bool isFloat) {
    if (s.size == 1) return allDigits(s.v[0], isFloat);
    return allDigits(glm::dvec3(s.v[0], s.v[1], s.v[2]), isFloat);
}

struct Outcome {
    bool hit = false;
    double t = 0, u = 0, v = 0;
    glm::dvec3 point{0.0};
    StepLog log;
};

/// The kernel and the hit point in T. Kept out of line (GCC's noipa, clang's optnone) so that
/// none of its arithmetic can be moved across the reading of the floating-point flags around it.
#if defined(__clang__)
#define RAYSTEP_OPAQUE [[gnu::noinline, clang::optnone]]
#else
#define RAYSTEP_OPAQUE [[gnu::noipa]]
#endif
template <typename T>
RAYSTEP_OPAQUE Outcome intersectIn(const glm::dvec3& o, const glm::dvec3& d, bool isTriangle,
                                   const std::vector<std::vector<double>>& shape, TriangleMethod tm,
                                   SphereMethod sm) {
    Outcome out;
    const TVec3<T> to(o), td(d);
    const T inf = std::numeric_limits<T>::infinity();
    if (isTriangle) {
        const TVec3<T> a(vec(shape[0])), b(vec(shape[1])), c(vec(shape[2]));
        if (const auto h = intersectTriangle<T>(tm, to, td, a, b, c, T(0), inf, out.log)) {
            out = {true,
                   double(h->t),
                   double(h->u),
                   double(h->v),
                   glm::dvec3(trianglePoint<T>(a, b, c, h->u, h->v).p),
                   std::move(out.log)};
        }
    } else {
        const TVec3<T> centre(vec(shape[0]));
        const T r = T(shape[1][0]);
        if (const auto t = intersectSphere<T>(sm, to, td, centre, r, T(0), inf, out.log)) {
            out.hit = true;
            out.t = double(*t);
            out.point = glm::dvec3(spherePoint<T>(to, td, *t, centre, r).p);
        }
    }
    return out;
}

/// Each input number must be a normal number of the precision (or 0): a float overflows past
/// 3.4e38 and loses digits below 1.2e-38. The first that is not, for the message.
std::optional<double> unrepresentable(bool isFloat,
                                      const std::vector<std::vector<double>>& groups) {
    if (!isFloat) return std::nullopt;
    for (const auto& g : groups)
        for (double x : g)
            if (x != 0.0 && !(std::abs(x) >= std::numeric_limits<float>::min() &&
                              std::abs(x) <= std::numeric_limits<float>::max()))
                return x;
    return std::nullopt;
}

}  // namespace

int runIntersect(const IntersectArgs& a) {
    const auto ray = parseGroups(a.ray, {3, 3});
    if (!ray) return fail("--ray " + a.ray + ": expected ox,oy,oz:dx,dy,dz (6 finite numbers)");
    const glm::dvec3 o = vec((*ray)[0]), d = vec((*ray)[1]);
    if (d == glm::dvec3(0.0)) return fail("--ray " + a.ray + ": the direction must not be zero");
    const bool isTriangle = !a.triangle.empty();
    if (!isTriangle && a.sphere.empty()) return fail("intersect: give --triangle or --sphere");
    const auto shape =
        isTriangle ? parseGroups(a.triangle, {3, 3, 3}) : parseGroups(a.sphere, {3, 1});
    if (!shape) {
        return isTriangle
                   ? fail("--triangle " + a.triangle +
                          ": expected ax,ay,az:bx,by,bz:cx,cy,cz (9 finite numbers)")
                   : fail("--sphere " + a.sphere + ": expected cx,cy,cz:r (4 finite numbers)");
    }
    if (!isTriangle && !((*shape)[1][0] > 0.0))
        return fail("--sphere " + a.sphere + ": the radius must be greater than 0");
    const auto precision = parsePrecision(a.precision);
    if (!precision) return fail("--precision " + a.precision + ": expected float or double");

    TriangleMethod tm = TriangleMethod::Watertight;
    SphereMethod sm = SphereMethod::Stable;
    if (!a.method.empty()) {
        if (isTriangle) {
            const auto m = parseTriangleMethod(a.method);
            if (!m)
                return fail("--method " + a.method +
                            ": triangle methods are plane, moller-trumbore, watertight");
            tm = *m;
        } else {
            const auto m = parseSphereMethod(a.method);
            if (!m) return fail("--method " + a.method + ": sphere methods are textbook, stable");
            sm = *m;
        }
    }
    const std::string methodName(isTriangle ? name(tm) : name(sm));
    const bool isFloat = *precision == Precision::Float;
    const std::string shapeOption =
        isTriangle ? "--triangle " + a.triangle : "--sphere " + a.sphere;
    if (const auto x = unrepresentable(isFloat, *ray))
        return fail("--ray " + a.ray + ": " + formatNumber(*x) +
                    " is not a normal float (1.2e-38 to 3.4e38)");
    if (const auto x = unrepresentable(isFloat, *shape))
        return fail(shapeOption + ": " + formatNumber(*x) +
                    " is not a normal float (1.2e-38 to 3.4e38)");
    // The kernels are exact while their arithmetic stays in the precision's normal range: any
    // overflow, underflow or NaN in this one computation means the answer cannot be trusted.
    std::feclearexcept(FE_ALL_EXCEPT);
    const Outcome r = isFloat ? intersectIn<float>(o, d, isTriangle, *shape, tm, sm)
                              : intersectIn<double>(o, d, isTriangle, *shape, tm, sm);
    const int flags = std::fetestexcept(FE_OVERFLOW | FE_UNDERFLOW | FE_INVALID);
    if (flags) {
        const KernelRange range = kernelRange(*precision);
        const char* what = (flags & FE_OVERFLOW)  ? "overflowed"
                           : (flags & FE_INVALID) ? "was not a number"
                                                  : "underflowed";
        return fail("intersect --ray " + a.ray + " " + shapeOption + ": the " + methodName +
                    " test in " + a.precision + " left the range it is exact in (a result " + what +
                    "); its answer would not be reliable. Scale the inputs to " +
                    formatNumber(range.smallest) + " .. " + formatNumber(range.largest) +
                    " with a direction of length about 1");
    }

    if (a.json) {
        nlohmann::ordered_json j;
        j["hit"] = r.hit;
        j["t"] = r.hit ? nlohmann::ordered_json(r.t) : nlohmann::ordered_json(nullptr);
        j["point"] = r.hit ? nlohmann::ordered_json{r.point.x, r.point.y, r.point.z}
                           : nlohmann::ordered_json(nullptr);
        if (isTriangle) {
            j["u"] = r.hit ? nlohmann::ordered_json(r.u) : nlohmann::ordered_json(nullptr);
            j["v"] = r.hit ? nlohmann::ordered_json(r.v) : nlohmann::ordered_json(nullptr);
        }
        j["method"] = methodName;
        j["precision"] = a.precision;
        nlohmann::ordered_json steps = nlohmann::ordered_json::object();
        for (const auto& s : r.log.steps)
            steps[s.name] = s.size == 1 ? nlohmann::ordered_json(s.v[0])
                                        : nlohmann::ordered_json{s.v[0], s.v[1], s.v[2]};
        j["steps"] = steps;
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    const auto p = [&](const glm::dvec3& v) { return allDigits(v, isFloat); };
    const auto num = [&](double x) { return allDigits(x, isFloat); };
    std::printf("ray        origin %s  direction %s\n", p(o).c_str(), p(d).c_str());
    if (isTriangle)
        std::printf("triangle   a %s  b %s  c %s\n", p(vec((*shape)[0])).c_str(),
                    p(vec((*shape)[1])).c_str(), p(vec((*shape)[2])).c_str());
    else
        std::printf("sphere     centre %s  radius %s\n", p(vec((*shape)[0])).c_str(),
                    num((*shape)[1][0]).c_str());
    std::printf("method     %s, in %s\n\n", methodName.c_str(), a.precision.c_str());
    for (const auto& s : r.log.steps)
        std::printf("  %-20s %s\n", s.name, stepText(s, isFloat).c_str());
    std::printf("\n");
    if (!r.hit) {
        std::printf("result     miss\n");
    } else if (isTriangle) {
        std::printf(
            "result     hit at t = %s\n           point %s\n"
            "           barycentric u = %s, v = %s (weights of a, b, c: %s, %s, %s)\n",
            num(r.t).c_str(), p(r.point).c_str(), num(r.u).c_str(), num(r.v).c_str(),
            num(1 - r.u - r.v).c_str(), num(r.u).c_str(), num(r.v).c_str());
    } else {
        std::printf("result     hit at t = %s\n           point %s\n", num(r.t).c_str(),
                    p(r.point).c_str());
    }
    return 0;
}

}  // namespace raystep::cli

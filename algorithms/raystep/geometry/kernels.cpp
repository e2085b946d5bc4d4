#include "raystep/geometry/kernels.h"

#include "raystep/base/names.h"

#include <cmath>
#include <cstdio>

namespace raystep {

namespace {
constexpr NameTable<Precision, 2> kPrecisionNames{
    {{Precision::Float, "float"}, {Precision::Double, "double"}}};
constexpr NameTable<SphereMethod, 2> kSphereNames{
    {{SphereMethod::Textbook, "textbook"}, {SphereMethod::Stable, "stable"}}};
constexpr NameTable<TriangleMethod, 3> kTriangleNames{
    {{TriangleMethod::Plane, "plane"},
     {TriangleMethod::MollerTrumbore, "moller-trumbore"},
     {TriangleMethod::Watertight, "watertight"}}};
constexpr NameTable<RayOffsetMethod, 2> kOffsetNames{
    {{RayOffsetMethod::Epsilon, "epsilon"}, {RayOffsetMethod::Robust, "robust"}}};
}  // namespace

std::optional<Precision> parsePrecision(std::string_view s) {
    return valueNamed(kPrecisionNames, s);
}
std::optional<SphereMethod> parseSphereMethod(std::string_view s) {
    return valueNamed(kSphereNames, s);
}
std::optional<TriangleMethod> parseTriangleMethod(std::string_view s) {
    return valueNamed(kTriangleNames, s);
}
std::optional<RayOffsetMethod> parseRayOffset(std::string_view s) {
    return valueNamed(kOffsetNames, s);
}
std::string_view name(Precision p) {
    return nameOf(kPrecisionNames, p);
}
std::string_view name(SphereMethod m) {
    return nameOf(kSphereNames, m);
}
std::string_view name(TriangleMethod m) {
    return nameOf(kTriangleNames, m);
}
std::string_view name(RayOffsetMethod m) {
    return nameOf(kOffsetNames, m);
}

KernelRange kernelRange(Precision p) {
    // 192 (2 largest)^4, the plane method's |n|^2, stays below the largest finite value by 1e66
    // (double) or 1e4 (float); smallest^4 stays above the smallest normal value by far more than
    // the precision's 2^52 (2^23), so the rounding errors of a scene's own size are normal.
    if (p == Precision::Float) return {1e-7, 1e8};
    return {1e-60, 1e60};
}

namespace {
std::string g3(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}
}  // namespace

std::optional<std::string> kernelRangeProblem(Precision p, double magnitude) {
    const KernelRange r = kernelRange(p);
    const auto g = g3;
    const std::string which = std::string(name(p));
    if (!std::isfinite(magnitude)) return "a coordinate is not a finite number";
    if (std::abs(magnitude) > r.largest)
        return "coordinates reach " + g(std::abs(magnitude)) + ", beyond " + g(r.largest) +
               " where the " + which + " intersection kernels are exact (their squares overflow)";
    if (std::abs(magnitude) < r.smallest)
        return "the whole scene lies within " + g(std::abs(magnitude)) + " of the origin, below " +
               g(r.smallest) + " where the " + which +
               " intersection kernels are exact (their products underflow)";
    return std::nullopt;
}

std::optional<std::string> primitiveRangeProblem(Precision p, double reach, double size) {
    const KernelRange r = kernelRange(p);
    if (!std::isfinite(reach) || !std::isfinite(size)) return "a coordinate is not a finite number";
    if (std::abs(reach) > r.largest)
        return "coordinates reach " + g3(std::abs(reach)) + ", beyond " + g3(r.largest) +
               " where the " + std::string(name(p)) +
               " intersection kernels are exact (their squares overflow)";
    if (size > 0.0 && size < r.smallest)
        return "its size is " + g3(size) + ", below " + g3(r.smallest) + " where the " +
               std::string(name(p)) +
               " intersection kernels are exact (its squares underflow to 0: every ray near it "
               "would hit)";
    return std::nullopt;
}

std::optional<std::string> rayRangeProblem(Precision p, double reach, double dirLargest) {
    const KernelRange r = kernelRange(p);
    if (!std::isfinite(reach) || !std::isfinite(dirLargest))
        return "a coordinate is not a finite number";
    if (std::abs(reach) > r.largest)
        return "the origin reaches " + g3(std::abs(reach)) + ", beyond " + g3(r.largest) +
               " where the " + std::string(name(p)) + " intersection kernels are exact";
    if (std::abs(dirLargest) > r.largest || std::abs(dirLargest) < r.smallest)
        return "the direction's largest component is " + g3(std::abs(dirLargest)) + ", outside " +
               g3(r.smallest) + " to " + g3(r.largest) + " where the " + std::string(name(p)) +
               " intersection kernels are exact (its square overflows "
               "or underflows)";
    return std::nullopt;
}

}  // namespace raystep

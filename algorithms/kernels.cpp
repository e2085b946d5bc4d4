#include "raystep/kernels.h"

#include "raystep/names.h"

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

}  // namespace raystep

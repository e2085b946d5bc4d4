#include "raystep/kernels.h"

namespace raystep {

std::optional<Precision> parsePrecision(std::string_view s) {
    if (s == "float") return Precision::Float;
    if (s == "double") return Precision::Double;
    return std::nullopt;
}
std::optional<SphereMethod> parseSphereMethod(std::string_view s) {
    if (s == "textbook") return SphereMethod::Textbook;
    if (s == "stable") return SphereMethod::Stable;
    return std::nullopt;
}
std::optional<TriangleMethod> parseTriangleMethod(std::string_view s) {
    if (s == "plane") return TriangleMethod::Plane;
    if (s == "moller-trumbore") return TriangleMethod::MollerTrumbore;
    if (s == "watertight") return TriangleMethod::Watertight;
    return std::nullopt;
}
std::optional<RayOffsetMethod> parseRayOffset(std::string_view s) {
    if (s == "epsilon") return RayOffsetMethod::Epsilon;
    if (s == "robust") return RayOffsetMethod::Robust;
    return std::nullopt;
}
std::string_view name(Precision p) {
    return p == Precision::Float ? "float" : "double";
}
std::string_view name(SphereMethod m) {
    return m == SphereMethod::Textbook ? "textbook" : "stable";
}
std::string_view name(TriangleMethod m) {
    switch (m) {
        case TriangleMethod::Plane:
            return "plane";
        case TriangleMethod::MollerTrumbore:
            return "moller-trumbore";
        case TriangleMethod::Watertight:
            break;
    }
    return "watertight";
}
std::string_view name(RayOffsetMethod m) {
    return m == RayOffsetMethod::Epsilon ? "epsilon" : "robust";
}

}  // namespace raystep

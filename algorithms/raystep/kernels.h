#pragma once
// Which intersection kernel, in which precision, and where secondary rays start: the numerical
// choices a user can trade for speed. The defaults are the accurate ones.
#include "raystep/intersect.h"

#include <optional>
#include <string_view>

namespace raystep {

enum class Precision { Float, Double };
enum class SphereMethod { Textbook, Stable };
enum class TriangleMethod { Plane, MollerTrumbore, Watertight };
enum class RayOffsetMethod { Epsilon, Robust };

struct KernelOptions {
    Precision precision = Precision::Double;
    SphereMethod sphere = SphereMethod::Stable;
    TriangleMethod triangle = TriangleMethod::Watertight;
};

std::optional<Precision> parsePrecision(std::string_view s);
std::optional<SphereMethod> parseSphereMethod(std::string_view s);
std::optional<TriangleMethod> parseTriangleMethod(std::string_view s);
std::optional<RayOffsetMethod> parseRayOffset(std::string_view s);
std::string_view name(Precision p);
std::string_view name(SphereMethod m);
std::string_view name(TriangleMethod m);
std::string_view name(RayOffsetMethod m);

/// Dispatch to the chosen ray-sphere kernel.
template <typename T, typename Steps = NoSteps>
std::optional<T> intersectSphere(SphereMethod m, const TVec3<T>& o, const TVec3<T>& d,
                                 const TVec3<T>& center, T radius, T tMin, T tMax,
                                 Steps&& steps = {}) {
    if (m == SphereMethod::Textbook)
        return intersectSphereTextbook<T>(o, d, center, radius, tMin, tMax, steps);
    return intersectSphereStable<T>(o, d, center, radius, tMin, tMax, steps);
}

/// Dispatch to the chosen ray-triangle kernel.
template <typename T, typename Steps = NoSteps>
std::optional<TriangleHit<T>> intersectTriangle(TriangleMethod m, const TVec3<T>& o,
                                                const TVec3<T>& d, const TVec3<T>& a,
                                                const TVec3<T>& b, const TVec3<T>& c, T tMin,
                                                T tMax, Steps&& steps = {}) {
    switch (m) {
        case TriangleMethod::Plane:
            return intersectTrianglePlane<T>(o, d, a, b, c, tMin, tMax, steps);
        case TriangleMethod::MollerTrumbore:
            return intersectTriangleMT<T>(o, d, a, b, c, tMin, tMax, steps);
        case TriangleMethod::Watertight:
            break;
    }
    return intersectTriangleWatertight<T>(o, d, a, b, c, tMin, tMax, steps);
}

}  // namespace raystep

#pragma once
// Which intersection kernel, in which precision, and where secondary rays start: the numerical
// choices a user can trade for speed. The defaults are the accurate ones.
#include "raystep/geometry/intersect.h"

#include <optional>
#include <string>
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

/// The magnitudes the kernels are exact in: with directions of length about 1 (the renderer's),
/// a scene whose largest coordinate or radius lies in [smallest, largest] keeps every quantity
/// the kernels form (up to fourth powers of coordinate differences, in the plane method) inside
/// the precision's normal range, with room for its rounding errors: nothing overflows, and
/// nothing underflows but quantities far below the scene's own rounding. Outside, squares
/// overflow to inf (every method misses) or underflow to 0 (a discriminant of -0: a wrong hit).
/// double: 1e-60 to 1e60; float: 1e-7 to 1e8.
struct KernelRange {
    double smallest;
    double largest;
};
KernelRange kernelRange(Precision p);

/// For a scene loader (or a command building rays by hand): nullopt if a scene whose largest
/// coordinate or radius in absolute value is `magnitude` lies in the kernels' range for `p`;
/// else the problem as one phrase ("coordinates reach 1e+200, beyond 1e+60 ..."). Cheap: check
/// it once per scene, not per ray.
std::optional<std::string> kernelRangeProblem(Precision p, double magnitude);
/// For one primitive: `reach` its largest coordinate in absolute value (a sphere's or circle's
/// centre plus radius), `size` its radius or longest edge (0 for a degenerate one, never hit).
/// Beyond the range its squares overflow; below it (a sphere of radius 1e-165) they underflow to
/// 0 and every ray near it would hit. nullopt if it is in the range.
std::optional<std::string> primitiveRangeProblem(Precision p, double reach, double size);
/// For a ray given by hand (2D rays are not normalised): `reach` of its origin, `dirLargest` the
/// largest component of its direction in absolute value.
std::optional<std::string> rayRangeProblem(Precision p, double reach, double dirLargest);

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

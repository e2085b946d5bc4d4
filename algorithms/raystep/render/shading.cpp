#include "raystep/render/shading.h"

namespace raystep {

PhongTerms phong(const Vec3& n, const Vec3& toLight, const Vec3& toViewer, const Color& lightI,
                 const Color& kd, const Color& ks, double shininess) {
    PhongTerms terms;
    const double cosA = glm::dot(n, toLight);
    if (cosA <= 0.0) return terms;  // light behind the surface: no diffuse, no highlight
    terms.diffuse = lightI * kd * cosA;
    const Vec3 mirrored = reflect(-toLight, n);
    const double cosB = glm::dot(mirrored, toViewer);
    if (cosB > 0.0) terms.specular = lightI * ks * std::pow(cosB, shininess);
    return terms;
}

std::optional<Vec3> refract(const Vec3& d, const Vec3& n, double eta) {
    const double cosI = -glm::dot(d, n);
    const double sin2T = eta * eta * std::max(0.0, 1.0 - cosI * cosI);
    if (sin2T >= 1.0) return std::nullopt;  // total internal reflection
    const double cosT = std::sqrt(1.0 - sin2T);
    return glm::normalize(eta * d + (eta * cosI - cosT) * n);
}

Vec3 cosineSampleHemisphere(const Vec3& n, double u1, double u2) {
    // Malley's method: uniform on the disc, lifted to the hemisphere.
    const double r = std::sqrt(u1);
    const double phi = 2.0 * kPi * u2;
    const double x = r * std::cos(phi);
    const double y = r * std::sin(phi);
    const double z = std::sqrt(std::max(0.0, 1.0 - u1));
    // Orthonormal basis around n (Duff et al. 2017).
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    const Vec3 t(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    const Vec3 bt(b, sign + n.y * n.y * a, -n.y);
    return glm::normalize(x * t + y * bt + z * n);
}

}  // namespace raystep

#include "raystep/scene/camera.h"

namespace raystep {

Ray Camera::generateRay(double x, double y, int width, int height) const {
    // Orthonormal camera frame; the loader has rejected eye == lookAt and up parallel to the view.
    const Vec3 forward = glm::normalize(lookAt - eye);
    const Vec3 right = glm::normalize(glm::cross(forward, up));
    const Vec3 trueUp = glm::cross(right, forward);
    const double halfHeight = std::tan(glm::radians(fovDeg) * 0.5);
    const double halfWidth = halfHeight * static_cast<double>(width) / static_cast<double>(height);
    const double sx = (2.0 * x / width - 1.0) * halfWidth;
    const double sy = (1.0 - 2.0 * y / height) * halfHeight;
    Ray ray;
    ray.origin = eye;
    ray.dir = glm::normalize(forward + sx * right + sy * trueUp);
    return ray;
}

}  // namespace raystep

#include "raystep/scene/camera.h"

#include <cmath>

namespace raystep {

Ray Camera::generateRay(double x, double y, int width, int height) const {
    return CameraRays(*this, width, height)(x, y);
}

CameraRays::CameraRays(const Camera& c, int w, int h) : width(w), height(h), eye_(c.eye) {
    // Orthonormal camera frame; the loader has rejected eye == lookAt and up parallel to the view.
    forward_ = glm::normalize(c.lookAt - c.eye);
    right_ = glm::normalize(glm::cross(forward_, c.up));
    up_ = glm::cross(right_, forward_);
    halfHeight_ = std::tan(glm::radians(c.fovDeg) * 0.5);
    halfWidth_ = halfHeight_ * static_cast<double>(w) / static_cast<double>(h);
}

Ray CameraRays::operator()(double x, double y) const {
    const double sx = (2.0 * x / width - 1.0) * halfWidth_;
    const double sy = (1.0 - 2.0 * y / height) * halfHeight_;
    Ray ray;
    ray.origin = eye_;
    ray.dir = glm::normalize(forward_ + sx * right_ + sy * up_);
    return ray;
}

bool cameraUsable(const Camera& c) {
    const Vec3 view = c.lookAt - c.eye;
    if (!(glm::length(view) > 0.0) || !std::isfinite(glm::length(view))) return false;
    const Vec3 side = glm::cross(glm::normalize(view), c.up);
    return glm::length(side) > 1e-9 && c.fovDeg > 0.0 && c.fovDeg < 180.0;
}

std::optional<glm::dvec2> imagePosition(const Camera& camera, const Vec3& dir, int width,
                                        int height) {
    const Vec3 forward = glm::normalize(camera.lookAt - camera.eye);
    const Vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const Vec3 trueUp = glm::cross(right, forward);
    const double depth = glm::dot(dir, forward);
    if (!(depth > 0.0)) return std::nullopt;
    const double halfHeight = std::tan(glm::radians(camera.fovDeg) * 0.5);
    const double halfWidth = halfHeight * static_cast<double>(width) / static_cast<double>(height);
    // The point on the image plane at distance 1, in generateRay's (sx, sy), then in pixels.
    const double sx = glm::dot(dir, right) / depth, sy = glm::dot(dir, trueUp) / depth;
    return glm::dvec2((sx / halfWidth + 1.0) * 0.5 * width, (1.0 - sy / halfHeight) * 0.5 * height);
}

}  // namespace raystep

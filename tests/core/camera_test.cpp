// Primary rays: "project the pixels onto the scene". Directions by hand from the field of view.
#include "raystep/scene/camera.h"

#include <gtest/gtest.h>

namespace raystep {
namespace {

void expectDir(const Ray& r, Vec3 expected) {
    expected = glm::normalize(expected);
    EXPECT_NEAR(r.dir.x, expected.x, 1e-12);
    EXPECT_NEAR(r.dir.y, expected.y, 1e-12);
    EXPECT_NEAR(r.dir.z, expected.z, 1e-12);
}

TEST(Camera, RaysThroughCentreEdgesAndCorner) {
    // fov 90: the top edge is 45 degrees above the view; a 2:1 image is twice as wide.
    Camera cam;
    cam.eye = Vec3(0, 0, 0);
    cam.lookAt = Vec3(0, 0, -1);
    cam.up = Vec3(0, 1, 0);
    cam.fovDeg = 90.0;
    const Ray centre = cam.generateRay(100, 50, 200, 100);
    EXPECT_EQ(centre.origin, Vec3(0.0));
    expectDir(centre, Vec3(0, 0, -1));
    expectDir(cam.generateRay(100, 0, 200, 100), Vec3(0, 1, -1));     // top edge
    expectDir(cam.generateRay(100, 100, 200, 100), Vec3(0, -1, -1));  // bottom edge
    expectDir(cam.generateRay(200, 50, 200, 100), Vec3(2, 0, -1));    // right edge
    expectDir(cam.generateRay(0, 0, 200, 100), Vec3(-2, 1, -1));      // top-left corner
}

TEST(Camera, FrameFollowsLookAtAndUp) {
    // Looking down -x with z up: right = forward x up = (-1,0,0) x (0,0,1) = (0,1,0).
    Camera cam;
    cam.eye = Vec3(5, 0, 0);
    cam.lookAt = Vec3(0, 0, 0);
    cam.up = Vec3(0, 0, 1);
    cam.fovDeg = 60.0;
    const double h = std::tan(glm::radians(30.0));
    expectDir(cam.generateRay(8, 0, 16, 16), Vec3(-1, 0, h));   // top edge leans up (+z)
    expectDir(cam.generateRay(16, 8, 16, 16), Vec3(-1, h, 0));  // right edge leans to +y
}

}  // namespace
}  // namespace raystep

// The render loop: progressive passes (coarse blocks first, then every pixel, then more samples)
// and the one pass of render() both end on the image of each pixel traced on its own, and stop
// when asked.
#include "raystep/render/render.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <atomic>

namespace raystep {
namespace {

/// A camera the scene never had: moved up and to the side, looking at another point.
Camera turnedCamera(const Scene& s) {
    Camera c = s.camera;
    c.eye = s.camera.eye + Vec3(1.7, 1.1, -0.4);
    c.lookAt = s.camera.lookAt + Vec3(0.2, -0.1, 0.0);
    c.fovDeg = 50.0;
    return c;
}

/// The app's passes: 8x8 blocks first, then the samples doubling.
RenderOptions progressive() {
    RenderOptions o;
    o.firstBlock = 8;
    o.refine = true;
    return o;
}

/// The independent reference: each pixel of a copy of the scene whose own camera is `camera`,
/// traced alone by Tracer::renderPixel, in no loop of the render's.
RenderResult referenceRender(Scene s, const Camera& camera, const RenderOptions& o,
                             AccelKind kind) {
    s.camera = camera;
    const Accelerator accel = buildAccelerator(s, kind);
    RenderOptions r = o;
    r.camera.reset();
    const Tracer tracer(s, accel, r.trace);
    RenderResult out;
    out.image = Image(r.width, r.height);
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            RayCounters pixel;
            out.image.at(x, y) = tracer.renderPixel(x, y, r, pixel);
            out.costPerPixel.push_back(pixel.traversal.primitiveTests);
            out.counters += pixel;
        }
    return out;
}

void expectSameImage(const Image& a, const Image& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    int differ = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        if (a.pixels[i] != b.pixels[i]) ++differ;
    EXPECT_EQ(differ, 0) << "pixels that differ, of " << a.pixels.size();
}

TEST(Progressive, PlanHalvesTheBlocksThenDoublesTheSamples) {
    const auto plan = progressivePlan(8, 6);
    const std::vector<std::pair<int, int>> want = {{8, 1}, {4, 1}, {2, 1}, {1, 1},
                                                   {1, 2}, {1, 4}, {1, 6}};
    ASSERT_EQ(plan.size(), want.size());
    for (std::size_t i = 0; i < plan.size(); ++i) {
        EXPECT_EQ(plan[i].block, want[i].first) << i;
        EXPECT_EQ(plan[i].samples, want[i].second) << i;
    }
    EXPECT_EQ(progressivePlan(1, 1).size(), 1u);
    // Without refining: the coarse passes, then every pixel with all its samples at once.
    const auto once = progressivePlan(1, 6, false);
    ASSERT_EQ(once.size(), 1u);
    EXPECT_EQ(once[0].block, 1);
    EXPECT_EQ(once[0].samples, 6);
    // After coarse passes, every pixel's first sample, then the other two at once.
    const auto coarse = progressivePlan(4, 3, false);
    const std::vector<std::pair<int, int>> coarseWant = {{4, 1}, {2, 1}, {1, 1}, {1, 3}};
    ASSERT_EQ(coarse.size(), coarseWant.size());
    for (std::size_t i = 0; i < coarse.size(); ++i) {
        EXPECT_EQ(coarse[i].block, coarseWant[i].first) << i;
        EXPECT_EQ(coarse[i].samples, coarseWant[i].second) << i;
    }
}

TEST(Render, OnePassAndPassesGiveEveryPixelAsTracedAlone) {
    // render() in its default one pass, and in the app's passes, against each pixel on its own.
    const Scene scene = loadBuiltinScene("cornell");
    const Accelerator accel = buildAccelerator(scene, AccelKind::Grid);
    // One pass; the app's passes; coarse passes then every remaining sample at once.
    for (const int plan : {0, 1, 2}) {
        RenderOptions o = plan == 1 ? progressive() : RenderOptions{};
        if (plan == 2) o.firstBlock = 4;
        o.width = 37;
        o.height = 29;
        o.spp = 3;
        o.trace.bounces = 2;
        o.trace.diffuseSamples = 2;
        o.threads = 2;
        const RenderResult r = render(scene, accel, o);
        const RenderResult ref = referenceRender(scene, scene.camera, o, AccelKind::Grid);
        SCOPED_TRACE(plan);
        EXPECT_FALSE(r.cancelled);
        expectSameImage(r.image, ref.image);
        EXPECT_EQ(r.costPerPixel, ref.costPerPixel);
        EXPECT_EQ(r.counters.totalRays(), ref.counters.totalRays());
        EXPECT_EQ(r.counters.traversal.primitiveTests, ref.counters.traversal.primitiveTests);
    }
}

TEST(Progressive, LastPassIsRenderOfTheSameCameraOneSample) {
    const Scene scene = loadBuiltinScene("whitted");
    const Accelerator accel = buildAccelerator(scene, AccelKind::KdTree);
    RenderOptions o = progressive();
    o.camera = turnedCamera(scene);
    o.width = 101;  // not a multiple of any block: the edges' blocks are cut
    o.height = 67;
    o.spp = 1;
    o.trace.bounces = 3;
    o.threads = 2;
    ProgressiveRender p(scene, accel, o);
    ASSERT_TRUE(p.run());
    EXPECT_EQ(p.passesDone(), 4u);
    const RenderResult ref = referenceRender(scene, *o.camera, o, AccelKind::KdTree);
    expectSameImage(p.image(), ref.image);
    EXPECT_EQ(p.costPerPixel(), ref.costPerPixel);
    // Each pixel traced once over the four passes: as many primary rays as pixels.
    EXPECT_EQ(p.counters()[RayKind::Primary], std::uint64_t(o.width) * o.height);
}

TEST(Progressive, LastPassIsRenderWithSamplesAndDiffuseBounces) {
    // Cornell: jittered samples and random diffuse directions, both from each pixel's stream.
    const Scene scene = loadBuiltinScene("cornell");
    const Accelerator accel = buildAccelerator(scene, AccelKind::Bvh);
    RenderOptions o = progressive();
    o.camera = turnedCamera(scene);
    o.width = 45;
    o.height = 38;
    o.spp = 5;  // passes of 1, 2, 4 then 5 samples: the last one not a power of two
    o.trace.bounces = 2;
    o.trace.diffuseSamples = 3;
    o.threads = 2;
    ProgressiveRender p(scene, accel, o);
    ASSERT_TRUE(p.run());
    EXPECT_EQ(p.lastPass()->samples, 5);
    const RenderResult ref = referenceRender(scene, *o.camera, o, AccelKind::Bvh);
    expectSameImage(p.image(), ref.image);
    EXPECT_EQ(p.costPerPixel(), ref.costPerPixel);
    EXPECT_EQ(p.counters()[RayKind::Primary], std::uint64_t(o.width) * o.height * o.spp);
    // render() with the camera as an option gives the same image too.
    RenderOptions r;
    r.width = o.width;
    r.height = o.height;
    r.spp = o.spp;
    r.trace = o.trace;
    r.camera = o.camera;
    expectSameImage(p.image(), render(scene, accel, r).image);
}

TEST(Progressive, CoarsePassesFillEachBlockWithItsTracedPixel) {
    const Scene scene = loadBuiltinScene("whitted");
    const Accelerator accel = buildAccelerator(scene, AccelKind::Bvh);
    RenderOptions o = progressive();
    o.camera = turnedCamera(scene);
    o.width = 70;
    o.height = 45;
    o.threads = 2;
    const RenderResult ref = referenceRender(scene, *o.camera, o, AccelKind::Bvh);
    ProgressiveRender p(scene, accel, o);
    std::uint64_t primaryBefore = 0, pixelsBefore = 0;
    for (const int block : {8, 4, 2}) {
        ASSERT_TRUE(p.nextPass());
        EXPECT_EQ(p.lastPass()->block, block);
        int wrong = 0;
        for (int y = 0; y < o.height; ++y)
            for (int x = 0; x < o.width; ++x)
                if (p.image().at(x, y) != ref.image.at(x / block * block, y / block * block))
                    ++wrong;
        EXPECT_EQ(wrong, 0) << "block " << block;
        // Only the new pixels were traced: the lattice's points minus the previous pass's.
        const std::uint64_t lattice =
            std::uint64_t((o.width + block - 1) / block) * ((o.height + block - 1) / block);
        EXPECT_EQ(p.counters()[RayKind::Primary] - primaryBefore, lattice - pixelsBefore);
        primaryBefore = p.counters()[RayKind::Primary];
        pixelsBefore = lattice;
    }
}

TEST(Progressive, CancelStopsThePassAndKeepsThePreviousPicture) {
    const Scene scene = loadBuiltinScene("whitted");
    const Accelerator accel = buildAccelerator(scene, AccelKind::Bvh);
    RenderOptions o = progressive();
    o.camera = scene.camera;
    o.width = 160;
    o.height = 120;
    o.spp = 4;
    o.threads = 2;
    ProgressiveRender p(scene, accel, o);
    ASSERT_TRUE(p.nextPass());
    const Image coarse = p.image();
    const std::uint64_t primary = p.counters()[RayKind::Primary];
    std::atomic<int> calls{0};
    // Stop at the third report: the pass must not go on over all its rows.
    EXPECT_FALSE(p.nextPass([&](double) { return ++calls < 3; }));
    EXPECT_TRUE(p.cancelled());
    EXPECT_TRUE(p.done());
    EXPECT_FALSE(p.nextPass());
    EXPECT_EQ(p.passesDone(), 1u);
    expectSameImage(p.image(), coarse);
    const std::uint64_t passPixels = 20u * 15u * 4u - 20u * 15u;  // the 4x4 lattice's new points
    EXPECT_LT(p.counters()[RayKind::Primary] - primary, passPixels);
    EXPECT_FALSE(p.run());
}

TEST(Progressive, RefusesBadOptions) {
    const Scene scene = loadBuiltinScene("whitted");
    const Accelerator accel = buildAccelerator(scene, AccelKind::Bvh);
    RenderOptions o = progressive();
    o.camera = scene.camera;
    o.width = 0;
    EXPECT_THROW(ProgressiveRender(scene, accel, o), std::invalid_argument);
    o.width = 10;
    o.spp = 0;
    EXPECT_THROW(ProgressiveRender(scene, accel, o), std::invalid_argument);
    o.spp = 1;
    o.firstBlock = 6;
    EXPECT_THROW(ProgressiveRender(scene, accel, o), std::invalid_argument);
    o.firstBlock = 8;
    o.camera->lookAt = o.camera->eye;
    EXPECT_THROW(ProgressiveRender(scene, accel, o), std::invalid_argument);
}

TEST(Camera, ImagePositionInvertsGenerateRay) {
    // fov 90, 200x100 (by hand): the direction (2, 0, -1) crosses the right edge's middle,
    // (-2, 1, -1) the top-left corner; a direction behind the eye crosses nothing.
    Camera cam;
    cam.eye = Vec3(0, 0, 0);
    cam.lookAt = Vec3(0, 0, -1);
    cam.up = Vec3(0, 1, 0);
    cam.fovDeg = 90.0;
    const auto right = imagePosition(cam, Vec3(2, 0, -1), 200, 100);
    ASSERT_TRUE(right);
    EXPECT_NEAR(right->x, 200.0, 1e-9);
    EXPECT_NEAR(right->y, 50.0, 1e-9);
    const auto corner = imagePosition(cam, Vec3(-2, 1, -1), 200, 100);
    ASSERT_TRUE(corner);
    EXPECT_NEAR(corner->x, 0.0, 1e-9);
    EXPECT_NEAR(corner->y, 0.0, 1e-9);
    EXPECT_FALSE(imagePosition(cam, Vec3(0, 0, 1), 200, 100));
    EXPECT_TRUE(cameraUsable(cam));
    cam.up = Vec3(0, 0, 1);  // along the view
    EXPECT_FALSE(cameraUsable(cam));
}

}  // namespace
}  // namespace raystep

// Small golden images: regressions in the whole pipeline show as pixel differences.
// The references are renders reviewed by eye when they were made (tests/data/golden/README.md);
// RAYSTEP_UPDATE_GOLDEN=1 rewrites them after an intended change.
#include "raystep/render/render.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <cstdlib>

namespace raystep {
namespace {

struct GoldenCase {
    const char* scene;
    int width, height, spp, bounces, diffuseSamples;
};

void PrintTo(const GoldenCase& c, std::ostream* os) {
    *os << c.scene;
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesReference) {
    const GoldenCase& g = GetParam();
    const Scene s = loadBuiltinScene(g.scene);
    RenderOptions opt;
    opt.width = g.width;
    opt.height = g.height;
    opt.spp = g.spp;
    opt.trace = {g.bounces, g.diffuseSamples};
    const Accelerator accel = buildAccelerator(s, AccelKind::BruteForce);
    const std::vector<std::uint8_t> rgb = toSrgb8(render(s, accel, opt).image);
    const std::string path = std::string(RAYSTEP_GOLDEN_DIR) + "/" + g.scene + ".png";

    if (const char* update = std::getenv("RAYSTEP_UPDATE_GOLDEN"); update && *update == '1') {
        writePng(path, rgb, g.width, g.height);
        GTEST_SKIP() << "rewrote " << path;
    }
    int w = 0, h = 0, n = 0;
    unsigned char* ref = stbi_load(path.c_str(), &w, &h, &n, 3);
    ASSERT_NE(ref, nullptr) << "missing golden image " << path;
    ASSERT_EQ(w, g.width);
    ASSERT_EQ(h, g.height);
    // Tolerance for other compilers and optimisation levels: a few levels on average, and
    // only a few pixels (an edge that rounding moves) allowed to differ a lot.
    double sumDiff = 0.0;
    int bigDiffs = 0;
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        const int d = std::abs(int(rgb[i]) - int(ref[i]));
        sumDiff += d;
        bigDiffs += d > 8;
    }
    stbi_image_free(ref);
    EXPECT_LE(sumDiff / rgb.size(), 0.5);
    EXPECT_LE(bigDiffs, static_cast<int>(rgb.size() / 200));
}

INSTANTIATE_TEST_SUITE_P(Scenes, Golden,
                         ::testing::Values(GoldenCase{"default", 64, 48, 1, 4, 0},
                                           GoldenCase{"whitted", 64, 48, 4, 6, 0},
                                           GoldenCase{"cornell", 32, 32, 2, 2, 4}),
                         [](const auto& info) { return std::string(info.param.scene); });

}  // namespace
}  // namespace raystep

// The local model and the secondary-ray directions against values computed by hand.
#include "raystep/render/shading.h"
#include "raystep/base/rng.h"

#include "expect_color.h"

#include <gtest/gtest.h>

namespace raystep {
namespace {

using test::expectColor;

TEST(Phong, DiffuseAndSpecularByHand) {
    // Light at cos a = 0.8 from the normal; the viewer sits exactly on the mirrored light ray.
    const Vec3 n(0, 0, 1), toLight(0, 0.6, 0.8), toViewer(0, -0.6, 0.8);
    const PhongTerms t = phong(n, toLight, toViewer, Color(1.0), Color(0.5), Color(0.25), 10.0);
    expectColor(t.diffuse, Color(0.4));    // 1 * 0.5 * 0.8
    expectColor(t.specular, Color(0.25));  // 1 * 0.25 * 1^10
}

TEST(Phong, SpecularFallsOffAsCosToTheN) {
    // Viewer along the normal: the mirrored light (0, -0.6, 0.8) makes cos b = 0.8; 0.8^2 = 0.64.
    const PhongTerms t = phong(Vec3(0, 0, 1), Vec3(0, 0.6, 0.8), Vec3(0, 0, 1), Color(2, 1, 0),
                               Color(0.5), Color(0.25), 2.0);
    expectColor(t.diffuse, Color(0.8, 0.4, 0.0));     // I * 0.5 * 0.8 per channel
    expectColor(t.specular, Color(0.32, 0.16, 0.0));  // I * 0.25 * 0.64
}

TEST(Phong, LightBehindGivesNothing) {
    const PhongTerms t = phong(Vec3(0, 0, 1), Vec3(0, 0.6, -0.8), Vec3(0, 0, 1), Color(1.0),
                               Color(0.5), Color(0.5), 1.0);
    expectColor(t.diffuse, Color(0.0));
    expectColor(t.specular, Color(0.0));
}

TEST(Snell, RefractsIntoDenserMedium) {
    // 45 degrees into glass (1 -> 1.5): sin t = sin 45 / 1.5.
    const Vec3 d = glm::normalize(Vec3(1, -1, 0));
    const auto t = refract(d, Vec3(0, 1, 0), 1.0 / 1.5);
    ASSERT_TRUE(t);
    const double sinT = std::sin(kPi / 4) / 1.5;
    EXPECT_NEAR(t->x, sinT, 1e-12);
    EXPECT_NEAR(t->y, -std::sqrt(1 - sinT * sinT), 1e-12);
    EXPECT_NEAR(t->z, 0.0, 1e-12);
}

TEST(Snell, NormalIncidenceGoesStraight) {
    const auto t = refract(Vec3(0, -1, 0), Vec3(0, 1, 0), 1.0 / 1.33);
    ASSERT_TRUE(t);
    EXPECT_NEAR(glm::length(*t - Vec3(0, -1, 0)), 0.0, 1e-15);
}

TEST(Snell, TotalInternalReflectionPastTheCriticalAngle) {
    // Glass to air: critical angle asin(1 / 1.5) = 41.81 degrees.
    const auto dirAt = [](double deg) {
        const double a = glm::radians(deg);
        return Vec3(std::sin(a), -std::cos(a), 0);
    };
    const auto below = refract(dirAt(41.0), Vec3(0, 1, 0), 1.5);
    ASSERT_TRUE(below);
    EXPECT_NEAR(below->x, 1.5 * std::sin(glm::radians(41.0)), 1e-12);
    EXPECT_FALSE(refract(dirAt(42.0), Vec3(0, 1, 0), 1.5));
    EXPECT_FALSE(refract(dirAt(89.0), Vec3(0, 1, 0), 1.5));
}

TEST(DiffuseBounce, CosineWeightedDirections) {
    // For density cos/pi on the hemisphere, E[cos] = 2/3 and E[cos^2] = 1/2.
    for (const Vec3 n : {Vec3(0, 0, 1), Vec3(0, 0, -1), glm::normalize(Vec3(1, -2, 0.5))}) {
        Pcg32 rng(7, 3);
        constexpr int kSamples = 200000;
        double sumCos = 0.0, sumCos2 = 0.0;
        for (int i = 0; i < kSamples; ++i) {
            const double u1 = rng.uniform();
            const Vec3 w = cosineSampleHemisphere(n, u1, rng.uniform());
            ASSERT_NEAR(glm::length(w), 1.0, 1e-12);
            const double c = glm::dot(w, n);
            ASSERT_GE(c, -1e-12);
            sumCos += c;
            sumCos2 += c * c;
        }
        // Standard error of the mean of cos is sqrt(1/18 / N) = 0.0005: 0.003 is six of them.
        EXPECT_NEAR(sumCos / kSamples, 2.0 / 3.0, 0.003);
        EXPECT_NEAR(sumCos2 / kSamples, 0.5, 0.003);
    }
}

TEST(Pcg32, ReferenceStreamAndUniformRange) {
    // First outputs of the reference pcg32 demo (seed 42, stream 54), from pcg-random.org.
    Pcg32 rng(42, 54);
    EXPECT_EQ(rng.next(), 0xa15c02b7u);
    EXPECT_EQ(rng.next(), 0x7b47f409u);
    EXPECT_EQ(rng.next(), 0xba1d3330u);
    for (int i = 0; i < 1000; ++i) {
        const double u = rng.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
    }
}

}  // namespace
}  // namespace raystep

// Ray-sphere and ray-triangle kernels on cases whose answers are exact by hand, in float and double.
#include "raystep/intersect.h"

#include <gtest/gtest.h>

namespace raystep {
namespace {

template <typename T>
class Kernels : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Kernels, Scalars);

template <typename T>
TVec3<T> v(double x, double y, double z) {
    return TVec3<T>(T(x), T(y), T(z));
}

TYPED_TEST(Kernels, SphereHitFromOutside) {
    using T = TypeParam;
    const auto t = intersectSphere<T>(v<T>(0, 0, 0), v<T>(0, 0, 1), v<T>(0, 0, 5), T(1), T(0),
                                      std::numeric_limits<T>::infinity());
    ASSERT_TRUE(t);
    EXPECT_EQ(*t, T(4));  // the near root |5 - 1|
}

TYPED_TEST(Kernels, SphereFromInsideHitsFarSide) {
    using T = TypeParam;
    const auto t = intersectSphere<T>(v<T>(0, 0, 0), v<T>(1, 0, 0), v<T>(0, 0, 0), T(2), T(0),
                                      std::numeric_limits<T>::infinity());
    ASSERT_TRUE(t);
    EXPECT_EQ(*t, T(2));
}

TYPED_TEST(Kernels, SphereUnnormalisedDirectionScalesT) {
    using T = TypeParam;
    const auto t = intersectSphere<T>(v<T>(0, 0, 0), v<T>(0, 0, 2), v<T>(0, 0, 5), T(1), T(0),
                                      std::numeric_limits<T>::infinity());
    ASSERT_TRUE(t);
    EXPECT_EQ(*t, T(2));  // the point (0, 0, 4) = o + 2 * (0, 0, 2)
}

TYPED_TEST(Kernels, SphereTangentAndMiss) {
    using T = TypeParam;
    const T inf = std::numeric_limits<T>::infinity();
    const auto tangent = intersectSphere<T>(v<T>(0, 0, 0), v<T>(0, 0, 1), v<T>(0, 1, 5), T(1), T(0), inf);
    ASSERT_TRUE(tangent);
    EXPECT_EQ(*tangent, T(5));  // touches at (0, 0, 5): a double root
    EXPECT_FALSE(intersectSphere<T>(v<T>(0, 0, 0), v<T>(0, 0, 1), v<T>(0, 3, 5), T(1), T(0), inf));
    // Behind the origin: both roots negative.
    EXPECT_FALSE(intersectSphere<T>(v<T>(0, 0, 0), v<T>(0, 0, -1), v<T>(0, 0, 5), T(1), T(0), inf));
    // The interval ends before the sphere.
    EXPECT_FALSE(intersectSphere<T>(v<T>(0, 0, 0), v<T>(0, 0, 1), v<T>(0, 0, 5), T(1), T(0), T(3.5)));
}

TYPED_TEST(Kernels, TriangleHitWithBarycentrics) {
    using T = TypeParam;
    const auto h = intersectTriangleMT<T>(v<T>(0.25, 0.5, 1), v<T>(0, 0, -1), v<T>(0, 0, 0),
                                          v<T>(1, 0, 0), v<T>(0, 1, 0), T(0),
                                          std::numeric_limits<T>::infinity());
    ASSERT_TRUE(h);
    EXPECT_EQ(h->t, T(1));
    EXPECT_EQ(h->u, T(0.25));  // weight of b = (1, 0, 0): the x coordinate
    EXPECT_EQ(h->v, T(0.5));   // weight of c = (0, 1, 0): the y coordinate
}

TYPED_TEST(Kernels, TriangleMissParallelAndOutOfRange) {
    using T = TypeParam;
    const T inf = std::numeric_limits<T>::infinity();
    const auto a = v<T>(0, 0, 0), b = v<T>(1, 0, 0), c = v<T>(0, 1, 0);
    EXPECT_FALSE(intersectTriangleMT<T>(v<T>(0.8, 0.8, 1), v<T>(0, 0, -1), a, b, c, T(0), inf));  // u+v > 1
    EXPECT_FALSE(intersectTriangleMT<T>(v<T>(-0.1, 0.5, 1), v<T>(0, 0, -1), a, b, c, T(0), inf)); // u < 0
    EXPECT_FALSE(intersectTriangleMT<T>(v<T>(0.2, 0.2, 1), v<T>(1, 0, 0), a, b, c, T(0), inf));   // parallel
    EXPECT_FALSE(intersectTriangleMT<T>(v<T>(0.2, 0.2, 1), v<T>(0, 0, 1), a, b, c, T(0), inf));   // behind
    EXPECT_FALSE(intersectTriangleMT<T>(v<T>(0.2, 0.2, 1), v<T>(0, 0, -1), a, b, c, T(0), T(0.5)));
}

}  // namespace
}  // namespace raystep

#pragma once
// Component-wise comparison of colours in GoogleTest.
#include "raystep/base/math.h"

#include <gtest/gtest.h>

namespace raystep::test {

inline void expectColor(const Color& c, const Color& e, double tol = 1e-12) {
    EXPECT_NEAR(c.r, e.r, tol);
    EXPECT_NEAR(c.g, e.g, tol);
    EXPECT_NEAR(c.b, e.b, tol);
}

}  // namespace raystep::test

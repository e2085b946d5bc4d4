// Built only in the sanitizer build (RAYSTEP_SANITIZE): proves the checks it promises are on.
#include <gtest/gtest.h>

namespace {

int toInt(double d) {
    volatile double v = d;  // volatile: the compiler cannot fold the cast away
    return static_cast<int>(v);
}

}  // namespace

// A double past int's range cast to int is undefined behaviour; only -fsanitize=float-cast-overflow
// reports it (GCC's -fsanitize=undefined leaves it out), and the build must then stop.
TEST(SanitizerBuild, FloatToIntOverflowIsCaught) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    volatile int sink = 0;
    EXPECT_DEATH(sink = toInt(1e30), "1e\\+30 is outside the range of representable values");
    (void)sink;
}

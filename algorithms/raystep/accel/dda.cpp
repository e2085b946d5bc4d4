#include "raystep/accel/dda.h"

#include <boost/multiprecision/cpp_int.hpp>

namespace raystep::detail {

namespace {
using Rational = boost::multiprecision::cpp_rational;

/// A value of the extended line: -inf, a rational, or +inf (only a plain tMin/tMax is infinite).
struct Extended {
    int infinite = 0;  // -1, 0 or +1
    Rational value;
};

Extended exactValue(const Crossing& c) {
    if (c.plain) {
        if (std::isinf(c.t)) return {c.t > 0 ? 1 : -1, Rational(0)};
        return {0, Rational(c.t)};
    }
    const Rational boundary =
        Rational(c.lo) + Rational(c.k) * (Rational(c.hi) - Rational(c.lo)) / Rational(c.res);
    return {0, (boundary - Rational(c.o)) / Rational(c.d)};
}
}  // namespace

int compareCrossingsExact(const Crossing& a, const Crossing& b) {
    // Rational(inf) throws: infinities are ordered here, and two equal ones tie (so an interval
    // from inf to inf, or from -inf to -inf, is empty, as it is for the exact walk).
    const Extended x = exactValue(a), y = exactValue(b);
    if (x.infinite || y.infinite) return (x.infinite > y.infinite) - (x.infinite < y.infinite);
    return (x.value > y.value) - (x.value < y.value);
}

}  // namespace raystep::detail

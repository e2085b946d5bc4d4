#include "raystep/dda.h"

#include <boost/multiprecision/cpp_int.hpp>

namespace raystep::detail {

namespace {
using Rational = boost::multiprecision::cpp_rational;

Rational exactValue(const Crossing& c) {
    if (c.plain) return Rational(c.t);
    const Rational boundary =
        Rational(c.lo) + Rational(c.k) * (Rational(c.hi) - Rational(c.lo)) / Rational(c.res);
    return (boundary - Rational(c.o)) / Rational(c.d);
}
}  // namespace

int compareCrossingsExact(const Crossing& a, const Crossing& b) {
    // Infinite plain values (tMax = inf) never reach here: the filter separates them.
    const Rational x = exactValue(a), y = exactValue(b);
    return (x > y) - (x < y);
}

}  // namespace raystep::detail

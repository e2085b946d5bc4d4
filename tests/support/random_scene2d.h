#pragma once
// A random 2D scene for the structure tests: circles and segments over 20 x 10, the same for a
// seed and a stream (each test file keeps its own stream, so its scenes stay as they were).
#include "raystep/base/rng.h"
#include "raystep/scene/scene2d.h"

#include <cstdint>

namespace raystep {

inline Scene2D randomScene2D(int count, std::uint64_t seed, std::uint64_t stream) {
    Pcg32 rng(seed, stream);
    Scene2D s;
    for (int i = 0; i < count; ++i) {
        const Vec2 p(rng.uniform() * 20, rng.uniform() * 10);
        if (i % 3 == 0)
            s.circles.push_back({p, 0.2 + rng.uniform()});
        else
            s.segments.push_back({p, p + Vec2(rng.uniform() * 4 - 2, rng.uniform() * 4 - 2)});
    }
    return s;
}

}  // namespace raystep

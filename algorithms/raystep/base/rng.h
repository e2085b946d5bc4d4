#pragma once
// PCG32 (O'Neill 2014): small, fast and the same stream on every platform, so a seed gives the
// same image everywhere. One generator per pixel makes images independent of the thread count.
#include <cstdint>

namespace raystep {

class Pcg32 {
  public:
    Pcg32(std::uint64_t seed, std::uint64_t stream) {
        inc_ = (stream << 1u) | 1u;
        state_ = 0;
        next();
        state_ += seed;
        next();
    }
    std::uint32_t next() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    /// Uniform in [0, 1).
    double uniform() { return next() * 0x1p-32; }

  private:
    std::uint64_t state_;
    std::uint64_t inc_;
};

}  // namespace raystep

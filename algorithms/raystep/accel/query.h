#pragma once
// What every acceleration structure reports about one query.
#include <cstdint>

namespace raystep {

/// What one query cost: counted in locals by the caller and summed per pixel.
struct TraversalCounters {
    std::uint64_t primitiveTests = 0;
    std::uint64_t nodeVisits = 0;    // grid cells walked, tree nodes entered
    std::uint64_t mailboxSkips = 0;  // primitives not tested again thanks to the mailbox
    TraversalCounters& operator+=(const TraversalCounters& o) {
        primitiveTests += o.primitiveTests;
        nodeVisits += o.nodeVisits;
        mailboxSkips += o.mailboxSkips;
        return *this;
    }
};

}  // namespace raystep

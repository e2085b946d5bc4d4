// The JSON of a built tree's statistics, in the field order the course's scripts read.
#include "tree_report.h"

#include <string>

namespace raystep::cli {

nlohmann::ordered_json statsJson(const BuildSummary& b) {
    const TreeStats& s = b.stats;
    nlohmann::ordered_json reasons;
    for (std::size_t i = 0; i < kLeafReasonNames.size(); ++i)
        reasons[std::string(kLeafReasonNames[i])] = s.leafReasons[i];
    return {
        {"structure", b.description},    {"nodes", s.nodes},        {"leaves", s.leaves},
        {"empty_leaves", s.emptyLeaves}, {"max_depth", s.maxDepth}, {"references", s.references},
        {"sah_cost", s.sahCost},         {"build_ms", s.buildMs},   {"leaf_reasons", reasons}};
}

}  // namespace raystep::cli

// alias_table.h — Walker's alias method (built with Vose's algorithm): draw
// index i with probability weight[i] / sum in O(1) from one uniform number and
// one coin, whatever the number of entries.
#pragma once

#include <cstdint>
#include <vector>

namespace wf {

struct AliasEntry {
    float probability; // keep i when the coin is below this, else take alias
    uint32_t alias;
    float pmf; // weight[i] / sum
};

// Weights must be finite and non-negative with a positive sum.
std::vector<AliasEntry> build_alias_table(const std::vector<double>& weights);

} // namespace wf

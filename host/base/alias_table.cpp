// alias_table.cpp — Vose's stable construction: entries below the mean are
// topped up from entries above it, so no probability ends outside [0, 1].
#include "base/alias_table.h"

#include <numeric>
#include <stdexcept>

namespace wf {

std::vector<AliasEntry> build_alias_table(const std::vector<double>& weights) {
    const double sum = std::accumulate(weights.begin(), weights.end(), 0.0);
    if (weights.empty() || !(sum > 0.0)) throw std::invalid_argument("alias table needs a positive weight");
    const size_t n = weights.size();
    std::vector<double> scaled(n);
    std::vector<AliasEntry> table(n);
    std::vector<uint32_t> small, large;
    for (size_t i = 0; i < n; ++i) {
        scaled[i] = weights[i] * static_cast<double>(n) / sum;
        table[i] = {1.0f, static_cast<uint32_t>(i), static_cast<float>(weights[i] / sum)};
        (scaled[i] < 1.0 ? small : large).push_back(static_cast<uint32_t>(i));
    }
    while (!small.empty() && !large.empty()) {
        const uint32_t s = small.back(), l = large.back();
        small.pop_back();
        table[s].probability = static_cast<float>(scaled[s]);
        table[s].alias = l;
        scaled[l] -= 1.0 - scaled[s];
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // Whatever remains is 1 up to rounding: it keeps itself.
    return table;
}

} // namespace wf

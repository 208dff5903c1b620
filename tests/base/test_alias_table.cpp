// test_alias_table.cpp — the alias table draws each index with probability
// weight / sum: checked exactly, by summing what each column contributes.
#include <gtest/gtest.h>

#include "base/alias_table.h"

namespace wf {
namespace {

// The probability of index i: column i kept, plus every column aliased to i.
std::vector<double> implied_distribution(const std::vector<AliasEntry>& table) {
    std::vector<double> p(table.size(), 0.0);
    for (size_t i = 0; i < table.size(); ++i) {
        p[i] += table[i].probability / table.size();
        p[table[i].alias] += (1.0 - table[i].probability) / table.size();
    }
    return p;
}

TEST(AliasTable, ReproducesTheWeights) {
    const std::vector<double> weights = {1.0, 0.0, 7.5, 2.0, 1e-6, 3.0, 0.25};
    const std::vector<AliasEntry> table = build_alias_table(weights);
    const double sum = 1.0 + 7.5 + 2.0 + 1e-6 + 3.0 + 0.25;
    const std::vector<double> p = implied_distribution(table);
    for (size_t i = 0; i < weights.size(); ++i) {
        EXPECT_NEAR(p[i], weights[i] / sum, 1e-7) << i;
        EXPECT_NEAR(table[i].pmf, weights[i] / sum, 1e-7) << i;
        EXPECT_GE(table[i].probability, 0.0f);
        EXPECT_LE(table[i].probability, 1.0f);
    }
}

TEST(AliasTable, ManyEqualWeightsKeepThemselves) {
    const std::vector<AliasEntry> table = build_alias_table(std::vector<double>(1000, 2.0));
    for (const AliasEntry& e : table) EXPECT_FLOAT_EQ(e.probability, 1.0f);
}

TEST(AliasTable, RejectsAllZero) {
    EXPECT_THROW(build_alias_table({0.0, 0.0}), std::invalid_argument);
    EXPECT_THROW(build_alias_table({}), std::invalid_argument);
}

} // namespace
} // namespace wf

// pipeline/bit_runs.hpp against the bits read one by one: every row length from 1 to 200 (across one,
// two and four words), rows of random bits at densities from none to all, plus runs that end exactly
// at a word's edge and at n. The runs must be maximal, in order, inside [0, n), and cover exactly the
// set bits below n (bits at and past n are clear, set or random in the words, and must be ignored).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "pipeline/bit_runs.hpp"

namespace gsdot3::pipeline::detail {
namespace {

TEST(BitRuns, RunsAreTheSetBitsBelowNMaximalAndInOrder) {
  std::mt19937_64 rng(20261208);
  long rows = 0;
  for (std::size_t n = 1; n <= 200; ++n)
    for (const double density : {0.0, 0.1, 0.5, 0.9, 1.0})
      for (int rep = 0; rep < 8; ++rep, ++rows) {
        std::vector<std::uint64_t> words((n + 63) / 64 + 1, 0);
        std::bernoulli_distribution bit(density), half(0.5);
        for (std::size_t k = 0; k < 64 * words.size(); ++k)
          if (k >= n ? rep % 2 == 1 && (rep == 1 || half(rng)) : bit(rng))
            words[k / 64] |= std::uint64_t{1} << (k % 64);
        if (rep == 7 && n > 64) words[0] |= std::uint64_t{1} << 63, words[1] &= ~std::uint64_t{1};  // ends at an edge
        std::vector<std::pair<std::size_t, std::size_t>> runs;
        for_each_bit_run(words.data(), n, [&](std::size_t a, std::size_t b) { runs.emplace_back(a, b); });
        std::vector<std::pair<std::size_t, std::size_t>> expected;
        for (std::size_t k = 0; k < n; ++k) {
          if (((words[k / 64] >> (k % 64)) & 1) == 0) continue;
          if (!expected.empty() && expected.back().second == k)
            ++expected.back().second;
          else
            expected.emplace_back(k, k + 1);
        }
        ASSERT_EQ(runs, expected) << "n " << n << ", density " << density << ", row " << rep;
      }
  EXPECT_EQ(rows, 200L * 5 * 8);
}

}  // namespace
}  // namespace gsdot3::pipeline::detail

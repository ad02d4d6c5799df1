// Sharded runs (`prove --shard K/N`, `prove merge`) give the unsplit run's ledger: verdict,
// counterexample count, figures, witnesses and every option variant, for several N (including more
// shards than a sweep has chunks) and for a claim whose sweeps depend on earlier ones
// (two-pass.max-s.vertex stops at the first s that wraps).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "proofs/claim.hpp"
#include "proofs/runner.hpp"
#include "proofs/shard.hpp"

namespace p = gsdot3::proofs;

namespace {
void expect_same(const p::outcome& a, const p::outcome& b, const std::string& what) {
  EXPECT_EQ(a.result, b.result) << what;
  EXPECT_EQ(a.domain_size, b.domain_size) << what;
  EXPECT_EQ(a.counterexamples, b.counterexamples) << what;
  EXPECT_EQ(a.figures, b.figures) << what;
  EXPECT_EQ(a.witnesses, b.witnesses) << what;
  EXPECT_EQ(a.note, b.note) << what;
}

std::vector<std::string> shards(const p::claim& c, unsigned n, const p::run_config& cfg) {
  std::vector<std::string> parts;
  for (unsigned k = n; k-- > 0;) parts.push_back(p::run_shard(c, {}, cfg, {k, n}));  // any order
  return parts;
}
}  // namespace

TEST(Shard, ParsesKOverN) {
  ASSERT_TRUE(p::parse_shard("0/1"));
  EXPECT_EQ(p::parse_shard("3/7")->k, 3u);
  EXPECT_EQ(p::parse_shard("3/7")->n, 7u);
  for (const char* bad : {"", "1", "1/1", "7/3", "-1/2", "1/0", "a/2", "1/2x", "1//2"}) EXPECT_FALSE(p::parse_shard(bad)) << bad;
}

TEST(Shard, MergedShardsEqualTheUnsplitRunForSeveralN) {
  p::run_config cfg;
  cfg.sweep.threads = 2;
  for (const char* id : {"eq5-eq7.split-multiply", "eq9.rgb-sum", "two-pass.max-s.vertex"}) {
    const p::claim* c = p::find_claim(id);
    ASSERT_NE(c, nullptr) << id;
    const auto whole = p::run_claim(*c, {}, cfg);
    const std::vector<unsigned> ns = std::string(id) == "two-pass.max-s.vertex" ? std::vector<unsigned>{2, 3}
                                                                                : std::vector<unsigned>{1, 2, 3, 7, 600};
    for (unsigned n : ns) {
      const auto m = p::merge_shards(shards(*c, n, cfg), cfg);
      const std::string what = std::string(id) + " N = " + std::to_string(n);
      expect_same(m.result.result, whole.result, what);
      ASSERT_EQ(m.result.variants.size(), whole.variants.size()) << what;
      for (std::size_t v = 0; v < whole.variants.size(); ++v) {
        EXPECT_EQ(m.result.variants[v].option, whole.variants[v].option);
        EXPECT_EQ(m.result.variants[v].value, whole.variants[v].value);
        EXPECT_EQ(m.result.variants[v].changed, whole.variants[v].changed);
        expect_same(m.result.variants[v].result, whole.variants[v].result, what + " variant " + std::to_string(v));
      }
      EXPECT_EQ(m.recomputed_chunks, 0u) << what << ": every chunk came from a part";
    }
  }
}

TEST(Shard, MergeRefusesIncompleteOrMixedParts) {
  p::run_config cfg;
  cfg.variants = false;
  const p::claim* c = p::find_claim("eq5-eq7.split-multiply");
  ASSERT_NE(c, nullptr);
  auto parts = shards(*c, 3, cfg);
  EXPECT_THROW(p::merge_shards({parts[0], parts[1]}, cfg), std::invalid_argument);            // one missing
  EXPECT_THROW(p::merge_shards({parts[0], parts[0], parts[1]}, cfg), std::invalid_argument);  // one twice
  const p::claim* other = p::find_claim("eq4.signed-multiply");
  ASSERT_NE(other, nullptr);
  auto mixed = parts;
  mixed[0] = p::run_shard(*other, {}, cfg, {2, 3});
  EXPECT_THROW(p::merge_shards(mixed, cfg), std::invalid_argument);
  EXPECT_THROW(p::merge_shards({"{}"}, cfg), std::invalid_argument);
  EXPECT_THROW(p::merge_shards({"not json"}, cfg), std::invalid_argument);
}

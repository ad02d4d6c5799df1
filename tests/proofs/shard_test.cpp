// Sharded runs (`prove --shard K/N`, `prove merge`) give the unsplit run's ledger: verdict,
// counterexample count, figures, witnesses and every option variant, for several N (including more
// shards than a sweep has chunks) and for a claim whose sweeps depend on earlier ones
// (two-pass.max-s.vertex stops at the first s that wraps); and a slice of the interpolated claim's
// brute force, whose whole domain is far too large to run unsplit here.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "proofs/claim.hpp"
#include "proofs/runner.hpp"
#include "proofs/shard.hpp"
#include "two_pass_triangle/triangle_brute_force.hpp"

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
  for (const char* bad : {"", "1", "1/1", "7/3", "-1/2", "1/0", "a/2", "1/2x", "1//2"})
    EXPECT_FALSE(p::parse_shard(bad)) << bad;
}

TEST(Shard, MergedShardsEqualTheUnsplitRunForSeveralN) {
  p::run_config cfg;
  cfg.sweep.threads = 2;
  for (const char* id : {"eq5-eq7.split-multiply", "eq9.rgb-sum", "two-pass.max-s.vertex"}) {
    const p::claim* c = p::find_claim(id);
    ASSERT_NE(c, nullptr) << id;
    const auto whole = p::run_claim(*c, {}, cfg);
    const std::vector<unsigned> ns = std::string(id) == "two-pass.max-s.vertex"
                                         ? std::vector<unsigned>{2, 3}
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
  EXPECT_THROW(p::merge_shards({parts[0], parts[1]}, cfg), std::invalid_argument);  // one missing
  try {
    p::merge_shards({parts[1]}, cfg);
    ADD_FAILURE() << "shards 0 and 2 of 3 are missing";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "shards 0,2 of 3 are missing (as Slurm's --array=0,2 names them)");
  }
  EXPECT_THROW(p::merge_shards({parts[0], parts[0], parts[1]}, cfg), std::invalid_argument);  // one twice
  const p::claim* other = p::find_claim("eq4.signed-multiply");
  ASSERT_NE(other, nullptr);
  auto mixed = parts;
  mixed[0] = p::run_shard(*other, {}, cfg, {2, 3});
  EXPECT_THROW(p::merge_shards(mixed, cfg), std::invalid_argument);
  EXPECT_THROW(p::merge_shards({"{}"}, cfg), std::invalid_argument);
  EXPECT_THROW(p::merge_shards({"not json"}, cfg), std::invalid_argument);
}

TEST(Shard, MissingShardsAreNamedAsSlurmArrayRanges) {
  EXPECT_EQ(p::missing_shards({true, true, true}), "");
  EXPECT_EQ(p::missing_shards({true, true, true, false}), "3");
  EXPECT_EQ(p::missing_shards({false, true, false, false, false, true, false}), "0,2-4,6");
  EXPECT_EQ(p::missing_shards(std::vector<bool>(4096, false)), "0-4095");
}

namespace {
namespace tt = gsdot3::proofs::two_pass::triangle;
void expect_same(const tt::brute_force_acc& a, const tt::brute_force_acc& b, const std::string& what) {
  EXPECT_EQ(a.pixels, b.pixels) << what;
  EXPECT_EQ(a.w_outside.count, b.w_outside.count) << what;
  for (std::size_t k = 0; k < tt::statement_count; ++k) {
    const auto &x = a.statement[k], &y = b.statement[k];
    EXPECT_EQ(x.checked, y.checked) << what << " statement " << k;
    EXPECT_EQ(x.violations.count, y.violations.count) << what << " statement " << k;
    EXPECT_EQ(x.violations.first, y.violations.first) << what << " statement " << k;
    EXPECT_EQ(x.ratio_ppm.max, y.ratio_ppm.max) << what << " statement " << k;
    EXPECT_EQ(x.ratio_ppm.arg_max, y.ratio_ppm.arg_max) << what << " statement " << k;
  }
}
}  // namespace

TEST(Shard, BruteForceSliceMergedEqualsTheUnsplitSliceForSeveralN) {
  // --brute-force of two-pass.max-s.interpolated is 2^24 full-size cases: too large to run whole
  // here, so its sweep is split on a slice, through the sweep engine's record / replay (the
  // partial ledgers' JSON around the same bytes is the claims' test above). The slice: 4 triangles
  // (lattice points (p0, 0), (1, 0), (0, 1) for p0 = 0..3, one of them degenerate) × every light triple.
  constexpr std::uint64_t first = std::uint64_t{(8 << 12 | 1 << 6) << 6}, count = 256;
  p::sweep_config cfg;
  cfg.threads = 2;
  const auto whole = tt::brute_force(cfg, first, count);
  EXPECT_GT(whole.pixels, 1000000u);
  for (unsigned n : {1u, 2u, 3u, 7u, 300u}) {
    auto replay = std::make_shared<p::shard_log>();
    replay->m = p::shard_log::mode::replay;
    for (unsigned k = n; k-- > 0;) {  // any order
      auto record = std::make_shared<p::shard_log>();
      record->k = k, record->n = n;
      p::sweep_config part = cfg;
      part.shard = record;
      (void)tt::brute_force(part, first, count);
      for (auto& s : record->sweeps) replay->sweeps.push_back(std::move(s));
    }
    p::sweep_config merge = cfg;
    merge.shard = replay;
    expect_same(tt::brute_force(merge, first, count), whole, "N = " + std::to_string(n));
    EXPECT_EQ(replay->recomputed, 0u) << "N = " << n << ": every chunk came from a part";
  }
}

// zprefill.single-light (section 3.1) against the argument written out, not through the model: a
// pass that replaces the DPB word leaves the last fragment of the largest Z with or without step 1;
// the 2002 baseline's additive first pass adds, without step 1, every fragment whose Z is at least
// every Z before it (fragment 1 always: Z starts cleared to 0), and with it only those of the largest
// Z, so the two differ exactly when the first fragment's Z is below the largest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "proofs/claim.hpp"
#include "proofs/runner.hpp"

namespace p = gsdot3::proofs;

TEST(ZPrefill, ProvenForThePapersMethodsAndTheBaselineDiffersWhereTheFirstFragmentIsHidden) {
  std::uint64_t sequences = 0, hidden_first = 0;
  for (int k = 1; k <= 6; ++k) {
    std::vector<int> z(static_cast<std::size_t>(k), 0);
    for (bool more = true; more;) {
      ++sequences;
      if (z.front() < *std::max_element(z.begin(), z.end())) ++hidden_first;
      more = false;
      for (auto& v : z)
        if (++v < k) {
          more = true;
          break;
        } else {
          v = 0;
        }
    }
  }
  EXPECT_EQ(sequences, 1u + 4u + 27u + 256u + 3125u + 46656u);
  const auto* c = p::find_claim("zprefill.single-light");
  ASSERT_NE(c, nullptr);
  const p::claim_result r = p::run_claim(*c, {}, p::run_config{});
  std::vector<const p::outcome*> runs{&r.result};
  for (const auto& v : r.variants) runs.push_back(&v.result);
  EXPECT_EQ(runs.size(), 4u);  // tfx_rounding, gouraud_fraction, blend_shift
  for (const p::outcome* o : runs) {
    EXPECT_EQ(o->result, p::verdict::proven);
    EXPECT_EQ(o->domain_size, 4 * sequences);
    EXPECT_EQ(o->integer("differ_two_pass"), 0);
    EXPECT_EQ(o->integer("differ_four_pass"), 0);
    EXPECT_EQ(o->integer("differ_gouraud"), 0);
    EXPECT_EQ(o->integer("differ_baseline"), static_cast<std::int64_t>(hidden_first));
  }
}

// spot.attenuation-blend (section 3.6) against closed forms written from the blend equation, not
// through the model: the blend (Cd − Cs)·As >> 7 + Cs with Cs = 128 is 128 + sh((d − 128)·a), HIGHLIGHT
// with vertex RGB a and alpha 128 − a is floor(d·a / 128) + 128 − a, the four-pass channel product of
// sphere component s and normal component b is sh(s·(b + 128)) − s (blend over the DPB byte 128 − s),
// where sh is the blend's >> 7: floor, or toward zero under blend_shift = truncate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>

#include "proofs/claim.hpp"
#include "proofs/runner.hpp"

namespace p = gsdot3::proofs;

namespace {

struct expected {
  std::int64_t lo[3], hi[3];  // exact, after pass 1, after pass 4
  std::uint64_t differ = 0;
};

expected closed_form(bool truncate) {
  auto sh = [&](int x) { return truncate ? x / 128 : (x >= 0 ? x / 128 : -((-x + 127) / 128)); };
  auto blend = [&](int d, int a) { return (128 + sh((d - 128) * a)) & 0xFF; };
  auto product = [&](int s, int b) { return ((sh(s * (b + 128)) + 128 - s) & 0xFF) - 128; };
  expected e{};
  std::fill(std::begin(e.lo), std::end(e.lo), std::numeric_limits<std::int64_t>::max());
  std::fill(std::begin(e.hi), std::end(e.hi), std::numeric_limits<std::int64_t>::min());
  auto add = [&](int k, std::int64_t v) { e.lo[k] = std::min(e.lo[k], v), e.hi[k] = std::max(e.hi[k], v); };
  for (int d = 0; d < 256; ++d)
    for (int a = 0; a <= 128; ++a) {
      const int highlight = d * a / 128 + 128 - a;
      if (blend(d, a) != highlight) ++e.differ;
      add(0, 128 * blend(d, a) - (128 * 128 - (128 - d) * a));
    }
  for (int s = -127; s <= 128; ++s)
    for (int b = -128; b <= 127; ++b)
      for (int a = 0; a <= 128; ++a) {
        const int q = product(s, b);
        add(1, 128 * product(128 - blend(128 - s, a), b) - a * q);
        add(2, 128 * (blend(q + 128, a) - 128) - a * q);
      }
  return e;
}

void expect_figures(const p::outcome& o, const expected& e, const std::string& run) {
  EXPECT_EQ(o.counterexamples, e.differ) << run;
  EXPECT_EQ(o.result, e.differ == 0 ? p::verdict::proven : p::verdict::refuted) << run;
  EXPECT_EQ(o.domain_size, 256u * 129u + 256u * 256u * 129u) << run;
  const char* names[3] = {"err", "after_pass1_err", "after_pass4_err"};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(o.integer(std::string(names[k]) + "_min_128ths"), e.lo[k]) << run << " " << names[k];
    EXPECT_EQ(o.integer(std::string(names[k]) + "_max_128ths"), e.hi[k]) << run << " " << names[k];
  }
}

TEST(SpotAttenuation, FiguresEqualTheClosedFormsUnderEveryOption) {
  const auto* c = p::find_claim("spot.attenuation-blend");
  ASSERT_NE(c, nullptr);
  const p::claim_result r = p::run_claim(*c, {}, p::run_config{});
  const expected floor = closed_form(false), truncate = closed_form(true);
  EXPECT_EQ(floor.differ, 0u);  // floor((d − 128)·a / 128) + 128 = floor(d·a / 128) − a + 128
  EXPECT_GT(truncate.differ, 0u);
  expect_figures(r.result, floor, "base");
  ASSERT_EQ(r.variants.size(), 2u);  // tfx_rounding = truncate, blend_shift = truncate
  for (const auto& v : r.variants)
    expect_figures(v.result, v.option == "blend_shift" ? truncate : floor, v.option + "=" + v.value);
}

}  // namespace

// alpha-layer.round-trip (section 3.1's dot-product layers in free alphas): the claim declares that no
// model option moves it, so it is evaluated here under every value of every option, each one proven
// over the domain it names (2^24 moves); and its unit, gs_methods::move_into_alpha, writes exactly
// (old & FBMSK) | (byte << 24) on hand-picked words, written out as integers.
#include <gtest/gtest.h>

#include <cstdint>

#include "gs_arith/options.hpp"
#include "gs_arith/pixel_pipeline.hpp"
#include "gs_methods/pass_registers.hpp"
#include "proofs/claim.hpp"
#include "proofs/runner.hpp"

namespace p = gsdot3::proofs;

TEST(AlphaLayer, ProvenUnderEveryModelOption) {
  const auto* c = p::find_claim("alpha-layer.round-trip");
  ASSERT_NE(c, nullptr);
  EXPECT_TRUE(c->depends_on.empty());
  int runs = 0;
  for (const auto& opt : gs::option_catalogue())
    for (const auto& value : opt.values) {
      gs::model_options o;
      ASSERT_FALSE(gs::set_option(o, opt.name, value).has_value()) << opt.name << "=" << value;
      const p::outcome r = c->evaluate(o, p::sweep_config{});
      EXPECT_EQ(r.result, p::verdict::proven) << opt.name << "=" << value;
      EXPECT_EQ(r.domain_size, 1u << 24);
      ++runs;
    }
  EXPECT_GT(runs, 10);
}

TEST(AlphaLayer, TheMoveWritesOnlyAlpha) {
  const gs::gs_registers regs = gsdot3::gs_methods::move_into_alpha.registers();
  for (const std::uint32_t old : {0x00000000u, 0xFFFFFFFFu, 0x12345678u, 0x80808080u})
    for (const unsigned b : {0x00u, 0x01u, 0x7Fu, 0x80u, 0xFEu, 0xFFu}) {
      const auto v = gs::u8::from_wrapped(b);
      const gs::rgba8 texel{v, v, v, v};
      const gs::fragment_colour cf = gs::fragment_colour::flat(gs::rgba8::from_u32(0x80808080u));
      EXPECT_EQ(gs::pixel_pipeline(regs, {cf, texel, old, 3, 5}, {}).out, (old & 0x00FFFFFFu) | b << 24)
          << std::hex << old << " " << b;
    }
}

// pipeline/span_batch.hpp against gs::pixel_pipeline pixel by pixel: runs along a row (add_row) and
// single pixels (add) give every pixel its own old word, texel, colour and window coordinates. The
// registers dither (DTHE = 1, PSMCT16 or PSMCT32 with a random DIMX) so that a pixel given another's
// x or y reads another dither offset.
#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/registers.hpp"
#include "pipeline/span_batch.hpp"

namespace {

using gsdot3::pipeline::detail::span_batch;

struct pixel {
  gs::rgba8 texel;
  gs::fragment_colour cf;
};

TEST(SpanBatch, RowsAndSinglePixelsEqualThePixelPipelineWithTheirOwnXAndY) {
  std::mt19937 rng(30);
  auto bits = [&](int n) { return static_cast<std::uint64_t>(rng()) & ((std::uint64_t{1} << n) - 1); };
  auto channel = [&] { return gs::gouraud_channel::from_saturated(static_cast<std::int64_t>(bits(15))); };
  const gs::model_options o;
  for (int trial = 0; trial < 200; ++trial) {
    gs::gs_registers regs;
    regs.PRIM = gs::decode_prim(0x10 | (bits(1) << 6));            // TME, ABE at random
    regs.TEX0_1 = gs::decode_tex0(bits(2) << 35 | bits(1) << 34);  // TFX, TCC
    auto selector = [&] { return rng() % 3; };                     // 3 is reserved
    regs.ALPHA_1 = gs::decode_alpha(selector() | selector() << 2 | selector() << 4 | selector() << 6 | bits(8) << 32);
    regs.FRAME_1 = gs::decode_frame(std::uint64_t{bits(1) != 0 ? 0x02u : 0x00u} << 24);
    regs.DTHE = gs::decode_dthe(1);
    regs.DIMX =
        gs::decode_dimx((static_cast<std::uint64_t>(rng()) << 32 | rng()) & 0x7777777777777777u);  // 3-bit entries
    std::vector<std::uint32_t> words(400);
    for (auto& w : words) w = static_cast<std::uint32_t>(rng());
    std::vector<std::uint32_t> want = words;
    {
      span_batch batch(regs, o);
      std::size_t at = 0;
      while (at < words.size()) {
        const int n = 1 + static_cast<int>(bits(7));  // runs longer and shorter than a batch
        if (at + static_cast<std::size_t>(n) > words.size()) break;
        const int x0 = static_cast<int>(bits(10)), y = static_cast<int>(bits(10));
        std::vector<pixel> px(static_cast<std::size_t>(n));
        for (auto& p : px)
          p = {gs::rgba8::from_u32(static_cast<std::uint32_t>(rng())), {channel(), channel(), channel(), channel()}};
        for (int k = 0; k < n; ++k) {
          const pixel& p = px[static_cast<std::size_t>(k)];
          std::uint32_t& w = want[at + static_cast<std::size_t>(k)];
          w = gs::pixel_pipeline(regs, {p.cf, p.texel, w, static_cast<unsigned>(x0 + k), static_cast<unsigned>(y)}, o)
                  .out;
        }
        if (bits(1) != 0) {
          batch.add_row(&words[at], x0, y, [&](auto&& put) {
            for (const pixel& p : px) put(p.texel.to_u32(), p.cf);
          });
        } else {
          for (int k = 0; k < n; ++k)
            batch.add(words[at + static_cast<std::size_t>(k)], px[static_cast<std::size_t>(k)].texel,
                      px[static_cast<std::size_t>(k)].cf, x0 + k, y);
        }
        at += static_cast<std::size_t>(n);
      }
    }  // the destructor flushes
    ASSERT_EQ(words, want) << "trial " << trial;
  }
}

}  // namespace

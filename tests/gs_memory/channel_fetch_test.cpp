// The channel-fetch sprite layout fetches every pixel's channel exactly once: every channel, every
// pixel of every page of buffers of several widths, through CLAMP_1's wrap and the PSMT8 address
// function (the memory model), against the PSMCT32 address of the pixel's byte.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "gs_memory/address.hpp"
#include "gs_memory/channel_fetch.hpp"
#include "gs_memory/texture_wrap.hpp"

namespace gs::mem {
namespace {

TEST(GsMemoryChannelFetch, EveryPixelsChannelIsFetchedExactlyOnce) {
  std::uint64_t fetched = 0;
  for (const std::uint32_t fbw : {1u, 3u, 8u})
    for (unsigned c = 0; c < 4; ++c) {
      const channel_fetch f = channel_fetch_sprites(c);
      const std::uint32_t dbp = 96;  // the DPB at page 3
      for (std::uint32_t py = 0; py < 2; ++py)
        for (std::uint32_t px = 0; px < fbw; ++px) {
          const std::uint32_t page_bp = dbp + 32 * (px + py * fbw);  // TEX0.TBP0 of this page
          std::vector<int> covered(64 * 32, 0);
          for (const fetch_sprite& s : f.sprites)
            for (std::uint32_t y = s.y0; y < s.y1; ++y)
              for (std::uint32_t x = s.x0; x < s.x1; ++x) {
                ++covered[y * 64 + x];
                const auto u = wrap_texel(f.CLAMP.WMS, s.u0 + static_cast<std::int32_t>(x - s.x0),
                                          fixed::u4::literal(7), f.CLAMP.MINU, f.CLAMP.MAXU);
                const auto v = wrap_texel(f.CLAMP.WMT, s.v0 + static_cast<std::int32_t>(y - s.y0),
                                          fixed::u4::literal(6), f.CLAMP.MINV, f.CLAMP.MAXV);
                const location texel = locate(
                    buffer{fixed::uint<14>::from_wrapped(page_bp), fixed::uint<6>::from_wrapped(2 * fbw), psm::PSMT8},
                    u, v);
                const location pixel =
                    locate(buffer{fixed::uint<14>::from_wrapped(dbp), fixed::uint<6>::from_wrapped(fbw), psm::PSMCT32},
                           64 * px + x, 32 * py + y);
                ASSERT_EQ(texel.byte, pixel.byte + c) << "FBW " << fbw << " channel " << c << " page (" << px << ", "
                                                      << py << ") pixel (" << x << ", " << y << ")";
                ++fetched;
              }
          for (int n : covered) ASSERT_EQ(n, 1);
        }
    }
  EXPECT_EQ(fetched, 4u * 2u * (1u + 3u + 8u) * 2048u);
}

}  // namespace
}  // namespace gs::mem

// The section 3.4 model (proofs/dpb_clear.hpp) against facts written another way: zsigma is the
// manual's "four 32x16 regions of each page swapped along the diagonals", the explicit-clear pass
// changes no DPB word and leaves the LAB in PSMCT32 order, and the texture buffer's reloads.
#include <gtest/gtest.h>

#include "proofs/dpb_clear.hpp"

namespace gsdot3::proofs {
namespace {

page_words pattern() {
  page_words w{};
  for (int p = 0; p < page_pixels; ++p)
    w[static_cast<std::size_t>(p)] = 0x11000000u | static_cast<std::uint32_t>(p * 2654435761u) >> 8;
  return w;
}

TEST(DpbClearModel, ZsigmaSwapsTheQuartersAlongTheDiagonals) {
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) ASSERT_EQ(zsigma(y * 64 + x), (y ^ 16) * 64 + (x ^ 32)) << x << "," << y;
}

TEST(DpbClearModel, ExplicitClearReadsEveryTexelAndWritesNoDpbWord) {
  const page_words before = pattern();
  for (const auto tb : {gs::texture_buffer::quarter_page, gs::texture_buffer::per_fragment, gs::texture_buffer::page,
                        gs::texture_buffer::draw_snapshot}) {
    const ilp_pass r = run_ilp_pass(before, dpb_clear::explicit_clear, gs::mem::psm::PSMZ24, tb);
    EXPECT_EQ(r.dpb_after, before);
    for (int p = 0; p < page_pixels; ++p) {
      ASSERT_EQ(r.fetched[static_cast<std::size_t>(p)], before[static_cast<std::size_t>(p)] & 0xFFu);
      ASSERT_EQ(r.lab[static_cast<std::size_t>(p)],
                static_cast<std::uint32_t>(p + 1) << 8 | (before[static_cast<std::size_t>(p)] & 0xFFu));
    }
  }
}

// z-trick: the Z write of the fragment that read P lands on P, so whatever the buffering, every
// texel is read intact, and the whole page ends with RGB 0x808080 and its alpha untouched (PSMZ24).
TEST(DpbClearModel, ZTrickClearsThePixelItHasJustRead) {
  const page_words before = pattern();
  const ilp_pass r = run_ilp_pass(before, dpb_clear::z_trick, gs::mem::psm::PSMZ24, gs::texture_buffer::per_fragment);
  for (int p = 0; p < page_pixels; ++p) {
    ASSERT_EQ(r.fetched[static_cast<std::size_t>(p)], before[static_cast<std::size_t>(p)] & 0xFFu);
    ASSERT_EQ(r.dpb_after[static_cast<std::size_t>(p)], 0x11808080u);
  }
}

}  // namespace
}  // namespace gsdot3::proofs

// Unit tests of the GS local-memory layout: the two formulations agree on every coordinate of a page,
// known values from the manual's figures, the channel-fetch mapping, round trips and aliasing.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "formats.hpp"
#include "gs_memory/address.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_memory/overlay.hpp"
#include "gs_memory/swizzle_bits.hpp"
#include "gs_memory/swizzle_tables.hpp"

namespace gs::mem {
namespace {

using test::all_layouts;
using test::all_psms;

buffer buf(psm p, std::uint32_t bp, std::uint32_t bw) {
  return buffer{fixed::uint<14>::from_wrapped(bp), fixed::uint<6>::from_wrapped(bw), p};
}

// Every coordinate of one page, every layout: tables == bit formulas, and the page is a bijection
// onto its 8 KiB.
TEST(GsMemoryLayout, FormulationsAgreeOnEveryCoordinateOfAPage) {
  for (const layout l : all_layouts) {
    const extent pg = page_size(l);
    const std::uint32_t bw = pg.w / 64;
    const std::uint32_t units = page_bytes * 8 / unit_bits(l);
    std::vector<int> hits(units, 0);
    std::uint64_t checked = 0;
    for (std::uint32_t y = 0; y < pg.h; ++y)
      for (std::uint32_t x = 0; x < pg.w; ++x) {
        const std::uint32_t a = tables::unit_address(l, 0, bw, x, y);
        ASSERT_EQ(a, bits::unit_address(l, 0, bw, x, y)) << test::name(l) << " (" << x << ", " << y << ")";
        ASSERT_LT(a, units);
        ++hits[a];
        ++checked;
      }
    EXPECT_EQ(checked, units) << test::name(l);
    for (std::uint32_t a = 0; a < units; ++a) ASSERT_EQ(hits[a], 1) << test::name(l) << " unit " << a;
  }
}

// Values read off the GS User's Manual's section 8 figures by hand (block arrangement of a page,
// column and pixel order inside a block), not from the tables.
TEST(GsMemoryLayout, KnownValuesFromTheManualFigures) {
  struct known {
    psm p;
    std::uint32_t x, y, byte;
    unsigned bit;
  };
  const known cases[] = {
      {psm::PSMCT32, 0, 0, 0, 0},      {psm::PSMCT32, 1, 0, 4, 0},       // pixel 1 = word 1
      {psm::PSMCT32, 0, 1, 8, 0},      {psm::PSMCT32, 2, 0, 16, 0},      // 2×2 word groups
      {psm::PSMCT32, 0, 2, 64, 0},     {psm::PSMCT32, 8, 0, 256, 0},     // column 1, block 1
      {psm::PSMCT32, 0, 8, 512, 0},    {psm::PSMCT32, 32, 0, 4096, 0},   // block 2, block 16
      {psm::PSMCT32, 63, 31, 8188, 0}, {psm::PSMCT32, 64, 0, 8192, 0},   // last word, next page
      {psm::PSMZ32, 0, 0, 6144, 0},    {psm::PSMZ32, 32, 16, 0, 0},      // Z: quarters swapped
      {psm::PSMCT16, 8, 0, 2, 0},      {psm::PSMCT16, 1, 0, 4, 0},       // halfwords 1, 2
      {psm::PSMCT16, 0, 8, 256, 0},    {psm::PSMCT16, 16, 0, 512, 0},    // block 1 below, 2 right
      {psm::PSMCT16S, 32, 0, 4096, 0}, {psm::PSMCT16S, 0, 32, 1024, 0},  // 16S: blocks 16, 4
      {psm::PSMZ16, 0, 0, 6144, 0},    {psm::PSMZ16S, 0, 0, 6144, 0},
      {psm::PSMT8, 1, 0, 4, 0},        {psm::PSMT8, 8, 0, 2, 0},  // byte 0 of word 1; byte 2
      {psm::PSMT8, 16, 0, 256, 0},     {psm::PSMT8, 0, 16, 512, 0},
      {psm::PSMT4, 1, 0, 4, 0},        {psm::PSMT4, 8, 0, 1, 0},  // nibble 8 = byte 4 lo; nibble 2
      {psm::PSMT4, 0, 16, 256, 0},     {psm::PSMT4, 32, 0, 512, 0},
      {psm::PSMT8H, 1, 0, 7, 0},       {psm::PSMT4HL, 1, 0, 7, 0},  // top byte of word 1
      {psm::PSMT4HH, 1, 0, 7, 4},      {psm::PSMCT24, 1, 0, 4, 0},
  };
  for (const auto& c : cases) {
    const location at = locate(buf(c.p, 0, page_size(layout_of(c.p)).w / 64), c.x, c.y);
    EXPECT_EQ(at.byte, c.byte) << static_cast<int>(c.p) << " (" << c.x << ", " << c.y << ")";
    EXPECT_EQ(at.bit, c.bit) << static_cast<int>(c.p) << " (" << c.x << ", " << c.y << ")";
  }
  // PSMT4 texel (1, 0) of nibble 8 and (0, 2) whose nibble is 65 (odd): the high half of byte 32.
  EXPECT_EQ(locate(buf(psm::PSMT4, 0, 2), 0, 2).byte, 32u);
  EXPECT_EQ(locate(buf(psm::PSMT4, 0, 2), 0, 2).bit, 4u);
  static_assert(locate(buffer{fixed::uint<14>{}, fixed::uint<6>::literal(1), psm::PSMCT32}, 8, 0).byte == 256);
}

// The channel-fetch mapping (gs-memory-facts; PCSX2 `ps_convert_rgba_8i` says the same): with the
// same base and TBW = 2·FBW, PSMT8 texel (u, v) is one byte of PSMCT32 pixel (x, y). An independent
// third formulation, checked on every texel of a PSMT8 page, for a sweep of widths.
TEST(GsMemoryLayout, Psmt8ViewOfAPsmct32BufferIsTheChannelFetchMapping) {
  for (std::uint32_t fbw : {1u, 2u, 3u, 5u, 10u}) {
    for (std::uint32_t v = 0; v < 128; ++v)
      for (std::uint32_t u = 0; u < 256 && u < fbw * 128; ++u) {
        std::uint32_t x = ((u & ~15u) >> 1) | (u & 7u);
        if (((v >> 2) & 1u) != ((v >> 1) & 1u)) x ^= 4u;
        const std::uint32_t y = ((v & ~3u) >> 1) | (v & 1u);
        const unsigned channel = (v & 2u) ? ((u & 8u) ? 3u : 1u) : ((u & 8u) ? 2u : 0u);  // R G B A = 0..3
        const location t8 = locate(buf(psm::PSMT8, 64, 2 * fbw), u, v);
        const location ct = locate(buf(psm::PSMCT32, 64, fbw), x, y);
        ASSERT_EQ(t8.byte, ct.byte + channel) << "FBW " << fbw << " texel (" << u << ", " << v << ")";
      }
  }
}

// The page overlay (gsdot3 mem view) of PSMT8 over PSMCT32 is the channel-fetch mapping, and every
// overlay cell names a pixel whose location holds the view texel's bits.
TEST(GsMemoryLayout, PageOverlayIsTheChannelFetchMapping) {
  const auto cells = page_overlay(psm::PSMCT32, psm::PSMT8);
  ASSERT_EQ(cells.size(), 128u * 64u);
  for (std::uint32_t v = 0; v < 64; ++v)
    for (std::uint32_t u = 0; u < 128; ++u) {
      std::uint32_t x = ((u & ~15u) >> 1) | (u & 7u);
      if (((v >> 2) & 1u) != ((v >> 1) & 1u)) x ^= 4u;
      const std::uint32_t y = ((v & ~3u) >> 1) | (v & 1u);
      const unsigned channel = (v & 2u) ? ((u & 8u) ? 3u : 1u) : ((u & 8u) ? 2u : 0u);
      const overlay_cell& c = cells[v * 128 + u];
      ASSERT_EQ(c.x, x) << u << "," << v;
      ASSERT_EQ(c.y, y) << u << "," << v;
      ASSERT_EQ(c.bit, 8 * channel) << u << "," << v;
    }
  for (const psm base : all_psms)
    for (const psm view : all_psms) {
      const auto ov = page_overlay(base, view);
      const extent pv = page_size(layout_of(view)), pb = page_size(layout_of(base));
      for (std::uint32_t i = 0; i < ov.size(); i += 97) {
        const location tv = locate(buf(view, 0, pv.w / 64), i % pv.w, i / pv.w);
        const location tb = locate(buf(base, 0, pb.w / 64), ov[i].x, ov[i].y);
        const std::uint32_t word_bit = tb.byte * 8 + tb.bit - upper_shift(base);
        ASSERT_EQ(tv.byte * 8 + tv.bit, word_bit + ov[i].bit)
            << static_cast<int>(base) << " / " << static_cast<int>(view);
      }
    }
}

// write -> read returns the value, and a write changes exactly the format's bits.
// zsigma's formula against the overlay of the two formats' pages, and against locate over a buffer
// of 3x2 pages: PSMZ32 pixel zsigma(x, y) and PSMCT32 pixel (x, y) are the same word.
TEST(GsMemoryLayout, ZsigmaIsThePsmz32PixelOfAPsmct32Word) {
  const std::vector<overlay_cell> cells = page_overlay(psm::PSMZ32, psm::PSMCT32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) {
      const overlay_cell& c = cells[static_cast<std::size_t>(y * 64 + x)];
      EXPECT_EQ(zsigma(x, y), (std::array<int, 2>{static_cast<int>(c.x), static_cast<int>(c.y)})) << x << "," << y;
      EXPECT_EQ(c.bit, 0u);
    }
  const buffer ct = buf(psm::PSMCT32, 64, 3), z = buf(psm::PSMZ32, 64, 3);
  int checked = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 192; ++x, ++checked) {
      const auto [zx, zy] = zsigma(x, y);
      ASSERT_EQ(locate(z, static_cast<std::uint32_t>(zx), static_cast<std::uint32_t>(zy)).byte,
                locate(ct, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)).byte)
          << x << "," << y;
      ASSERT_EQ(zsigma(zx, zy), (std::array<int, 2>{x, y}));
    }
  EXPECT_EQ(checked, 192 * 64);
}

TEST(GsMemoryPixels, RoundTripAndNoOtherBitChanges) {
  std::mt19937 rng(14);
  for (const psm p : all_psms) {
    local_memory m;
    constexpr std::uint32_t span = 6 * page_bytes;  // BP 3, 128×64 pixels: at most 5 pages
    for (std::uint32_t a = 0; a < span; ++a) m.set_byte(a, static_cast<std::uint8_t>(rng()));
    const buffer b = buf(p, 3, 2);
    const std::uint32_t mask = value_bits(p) == 32 ? ~0u : (1u << value_bits(p)) - 1;
    for (int i = 0; i < 300; ++i) {
      const std::uint32_t x = rng() % 128, y = rng() % 64, v = rng();
      std::vector<std::uint8_t> before(span);
      for (std::uint32_t a = 0; a < span; ++a) before[a] = m.byte(a);
      m.write_pixel(b, x, y, v);
      ASSERT_EQ(m.read_pixel(b, x, y), v & mask) << static_cast<int>(p);
      const location at = locate(b, x, y);
      ASSERT_LT(at.byte + 4, span);
      for (std::uint32_t a = 0; a < span; ++a) {
        if (a >= at.byte && a < at.byte + 4) continue;
        ASSERT_EQ(m.byte(a), before[a]) << static_cast<int>(p) << " byte " << a;
      }
      // Inside the word the bits outside [bit, bit + bits) stay.
      std::uint64_t w0 = 0, w1 = 0;
      for (unsigned k = 0; k < 4; ++k) {
        w0 |= std::uint64_t{before[at.byte + k]} << (8 * k);
        w1 |= std::uint64_t{m.byte(at.byte + k)} << (8 * k);
      }
      const std::uint64_t field = std::uint64_t{mask} << at.bit;
      ASSERT_EQ(w0 & ~field, w1 & ~field) << static_cast<int>(p);
    }
  }
}

// PSMT8H / PSMT4HL / PSMT4HH alias bits 24-31 / 24-27 / 28-31 of the PSMCT32 word at the same
// (x, y); PSMCT24 and PSMZ24 leave bits 24-31 alone (manual section 8).
TEST(GsMemoryPixels, UpperFormatsAliasTheTopBitsOfPsmct32Words) {
  std::mt19937 rng(7);
  local_memory m;
  struct alias {
    psm p;
    psm base;
    std::uint32_t field;
    unsigned shift;
  };
  const alias cases[] = {{psm::PSMT8H, psm::PSMCT32, 0xffu, 24},
                         {psm::PSMT4HL, psm::PSMCT32, 0xfu, 24},
                         {psm::PSMT4HH, psm::PSMCT32, 0xfu, 28},
                         {psm::PSMCT24, psm::PSMCT32, 0xffffffu, 0},
                         {psm::PSMZ24, psm::PSMZ32, 0xffffffu, 0}};
  for (const auto& c : cases)
    for (std::uint32_t y = 0; y < 64; ++y)
      for (std::uint32_t x = 0; x < 128; ++x) {
        const std::uint32_t w = rng(), v = rng();
        m.write_pixel(buf(c.base, 32, 2), x, y, w);
        m.write_pixel(buf(c.p, 32, 2), x, y, v);
        const std::uint32_t expect = (w & ~(c.field << c.shift)) | ((v & c.field) << c.shift);
        ASSERT_EQ(m.read_pixel(buf(c.base, 32, 2), x, y), expect) << static_cast<int>(c.p) << " " << x << "," << y;
        ASSERT_EQ(m.read_pixel(buf(c.p, 32, 2), x, y), v & c.field);
      }
}

TEST(GsMemoryLayout, PageBasePointersAndLocationFields) {
  EXPECT_EQ(from_page(fixed::uint<9>::literal(5)).value(), 160);
  const location at = locate(buf(psm::PSMCT32, 160, 1), 8, 2);  // block 1 of page 5, column 1
  EXPECT_EQ(at.page(), 5u);
  EXPECT_EQ(at.block(), 161u);
  EXPECT_EQ(at.column(), 1u);
  // The last block wraps to the start of memory (4 MiB, 16384 blocks).
  EXPECT_EQ(locate(buf(psm::PSMCT32, 16383, 1), 8, 0).byte, 0u);
}

}  // namespace
}  // namespace gs::mem

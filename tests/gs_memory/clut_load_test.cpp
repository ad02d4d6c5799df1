// CSM2 and 16-bit CLUT loads against direct construction: palettes placed pixel by pixel with
// write_pixel (CSM2: a row at (16·COU, COV); CSM1: the manual's 8×2 entry arrangement written by
// hand), and the expected CLUT buffer built as 512 halves in a plain array.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>

#include "gs_memory/clut_load.hpp"

namespace gs::mem {
namespace {

template <int N>
fixed::uint<N> u(std::uint32_t v) {
  return fixed::uint<N>::from_wrapped(v);
}

// The CLUT buffer as 512 halves: entry i of a 32-bit buffer is halves i (low) and 256 + i (high).
std::array<std::uint16_t, 512> halves_of(const clut_buffer& b) {
  std::array<std::uint16_t, 512> h{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    h[i] = static_cast<std::uint16_t>(b[i].to_u32() & 0xFFFF);
    h[256 + i] = static_cast<std::uint16_t>(b[i].to_u32() >> 16);
  }
  return h;
}
// CSM1's arrangement by hand: within 32 entries, 0-7 row 0 left, 8-15 row 1 left, 16-23 row 0
// right, 24-31 row 1 right; each next 32 entries two rows lower.
std::pair<std::uint32_t, std::uint32_t> csm1_xy(std::uint32_t i) {
  const std::uint32_t k = i % 32;
  return {(k / 16) * 8 + k % 8, 2 * (i / 32) + (k / 8) % 2};
}
clut_buffer random_buffer(std::mt19937& rng) {
  clut_buffer b{};
  for (auto& e : b) e = rgba8::from_u32(rng());
  return b;
}

TEST(GsMemoryClut, Csm2ReadsOneRowAtCouCovAndIgnoresCsa) {
  std::mt19937 rng(31);
  for (const clut_psm cp : {clut_psm::PSMCT32, clut_psm::PSMCT16, clut_psm::PSMCT16S})
    for (const psm index : {psm::PSMT8, psm::PSMT4, psm::PSMT8H, psm::PSMT4HH}) {
      const psm p = cp == clut_psm::PSMCT32 ? psm::PSMCT32 : cp == clut_psm::PSMCT16 ? psm::PSMCT16 : psm::PSMCT16S;
      const std::uint32_t n = value_bits(index) == 8 ? 256 : 16, cou = 3, cov = 21;
      local_memory m;
      const buffer at{u<14>(640), u<6>(10), p};
      std::array<std::uint32_t, 256> entry{};
      for (std::uint32_t i = 0; i < n; ++i) {
        entry[i] = rng() & (p == psm::PSMCT32 ? 0xFFFFFFFFu : 0xFFFFu);
        m.write_pixel(at, 16 * cou + i, cov, entry[i]);
      }
      m.write_pixel(at, 16 * cou + n, cov, 0xDEADu);  // the pixel after the row is not loaded
      tex0_reg t;
      t.PSM = index;
      t.CBP = u<14>(640);
      t.CPSM = cp;
      t.CSM = true;
      t.CSA = fixed::u5::from_wrapped(7);
      t.CLD = u3::from_wrapped(1);
      const clut_state before{random_buffer(rng), {}, {}};
      const clut_state s = load_clut(m, t, before, {u<6>(10), u<6>(cou), u<10>(cov)});
      std::array<std::uint16_t, 512> expect = halves_of(before.buffer);
      for (std::uint32_t i = 0; i < n; ++i) {
        expect[i] = static_cast<std::uint16_t>(entry[i] & 0xFFFF);
        if (p == psm::PSMCT32) expect[256 + i] = static_cast<std::uint16_t>(entry[i] >> 16);
      }
      ASSERT_EQ(halves_of(s.buffer), expect) << "CPSM " << static_cast<int>(cp) << ", PSM " << static_cast<int>(index);
      for (std::uint32_t j = 0; j < 512; ++j) ASSERT_EQ(clut_half(s.buffer, j), expect[j]);
    }
}

TEST(GsMemoryClut, Csm1SixteenBitPalettesGoToHalvesFromSixteenTimesCsa) {
  std::mt19937 rng(32);
  for (const clut_psm cp : {clut_psm::PSMCT16, clut_psm::PSMCT16S})
    for (const std::uint32_t csa : {0u, 5u, 16u, 31u})
      for (const psm index : {psm::PSMT8, psm::PSMT4}) {
        const psm p = cp == clut_psm::PSMCT16 ? psm::PSMCT16 : psm::PSMCT16S;
        const std::uint32_t n = index == psm::PSMT8 ? 256 : 16;
        local_memory m;
        const buffer image{u<14>(2000), u<6>(1), p};
        std::array<std::uint16_t, 256> entry{};
        for (std::uint32_t i = 0; i < n; ++i) {
          entry[i] = static_cast<std::uint16_t>(rng());
          const auto [x, y] = n == 256 ? csm1_xy(i) : std::pair<std::uint32_t, std::uint32_t>{i % 8, i / 8};
          m.write_pixel(image, x, y, entry[i]);
        }
        tex0_reg t;
        t.PSM = index;
        t.CBP = u<14>(2000);
        t.CPSM = cp;
        t.CSA = fixed::u5::from_wrapped(csa);
        t.CLD = u3::from_wrapped(1);
        const clut_state before{random_buffer(rng), {}, {}};
        std::array<std::uint16_t, 512> expect = halves_of(before.buffer);
        for (std::uint32_t i = 0; i < n; ++i) expect[(16 * csa + i) % 512] = entry[i];
        ASSERT_EQ(halves_of(load_clut(m, t, before).buffer), expect) << "CSA " << csa << ", " << n << " entries";
      }
}

// A 16-bit load into the upper halves overwrites the B and A bytes of 32-bit entries already there.
TEST(GsMemoryClut, SixteenBitLoadsShareTheBufferWithThirtyTwoBitEntries) {
  local_memory m;
  const buffer image{u<14>(100), u<6>(1), psm::PSMCT16};
  for (std::uint32_t i = 0; i < 16; ++i) m.write_pixel(image, i % 8, i / 8, 0x7000u + i);
  clut_state s;
  for (std::uint32_t i = 0; i < 256; ++i) s.buffer[i] = rgba8::from_u32(0x11223344u);
  tex0_reg t;
  t.PSM = psm::PSMT4;
  t.CBP = u<14>(100);
  t.CPSM = clut_psm::PSMCT16;
  t.CSA = fixed::u5::from_wrapped(17);  // halves 272..287 = the upper halves of entries 16..31
  t.CLD = u3::from_wrapped(1);
  s = load_clut(m, t, s);
  for (std::uint32_t i = 0; i < 256; ++i)
    ASSERT_EQ(s.buffer[i].to_u32(), i >= 16 && i < 32 ? (0x7000u + i - 16) << 16 | 0x3344u : 0x11223344u)
        << "entry " << i;
}

TEST(GsMemoryRegisters, TexclutFields) {
  const texclut_reg r = decode_texclut(5u | 9u << 6 | 1000u << 12);
  EXPECT_EQ(r.CBW.value(), 5);
  EXPECT_EQ(r.COU.value(), 9);
  EXPECT_EQ(r.COV.value(), 1000);
  EXPECT_EQ(encode(r), 5u | 9u << 6 | 1000u << 12);
  EXPECT_THROW(decode_texclut(std::uint64_t{1} << 22), register_error);
}

}  // namespace
}  // namespace gs::mem

// Every SIMD unit whose input domain has at most 2^32 values, over that whole domain, against its
// scalar gs_arith unit (the reference), on the target dispatch picks for this CPU (property_test.cpp
// covers every target on random inputs). Each test names its domain and its size.
#include <gtest/gtest.h>

#include <cstdint>

#include "lanes.hpp"

namespace gsdot3::simd::test {
namespace {

constexpr std::size_t lanes = 1 << 16;

// modulate: Ct (2^8) × Cf 8.7 (2^15) × tfx_rounding (2) × gouraud_fraction (2) = 2^25.
TEST(SimdExhaustive, ModulateOverEveryTexelColourAndOption) {
  block b(lanes);
  std::size_t wrong = 0, seen = 0;
  for (const auto tfx : {gs::tfx_rounding::floor, gs::tfx_rounding::truncate})
    for (const auto gouraud : {gs::gouraud_fraction::keep_fraction, gs::gouraud_fraction::truncate_to_8}) {
      unit_call c{unit::modulate};
      c.options.tfx = tfx, c.options.gouraud = gouraud;
      for (std::uint32_t start = 0; start < (1u << 23); start += lanes) {
        for (std::size_t i = 0; i < lanes; ++i) {
          const std::uint32_t v = start + static_cast<std::uint32_t>(i);
          b.in[0][i] = static_cast<std::int32_t>(v & 0xFF), b.in[1][i] = static_cast<std::int32_t>(v >> 8);
        }
        b.run(c);
        wrong += compare(
            b, 1,
            [&](const block& k, std::size_t i) -> std::array<std::int32_t, 3> {
              return {gs::modulate_channel(gs::u8::from_wrapped(k.in[0][i]),
                                           gs::gouraud_channel::from_wrapped(k.in[1][i]), c.options)
                          .value()};
            },
            "modulate");
        seen += lanes;
      }
    }
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(seen, std::size_t{1} << 25);
}

// alpha_test: A (2^8) × AREF (2^8) × ATST (8) × AFAIL (4) × ATE (2) × FRAME.PSM (8) × rgb_only_targets (2) = 2^26.
TEST(SimdExhaustive, AlphaTestOverEveryAlphaReferenceAndMode) {
  static constexpr gs::frame_psm formats[] = {gs::frame_psm::PSMCT32,  gs::frame_psm::PSMCT24, gs::frame_psm::PSMCT16,
                                              gs::frame_psm::PSMCT16S, gs::frame_psm::PSMZ32,  gs::frame_psm::PSMZ24,
                                              gs::frame_psm::PSMZ16,   gs::frame_psm::PSMZ16S};
  block b(256);
  for (std::size_t i = 0; i < 256; ++i) b.in[0][i] = static_cast<std::int32_t>(i);
  std::size_t wrong = 0, seen = 0;
  for (int aref = 0; aref < 256; ++aref)
    for (int atst = 0; atst < 8; ++atst)
      for (int afail = 0; afail < 4; ++afail)
        for (bool ate : {false, true})
          for (const gs::frame_psm psm : formats)
            for (const auto rgb_only : {gs::rgb_only_targets::thirty_two_bit_only, gs::rgb_only_targets::all_formats}) {
              unit_call c{unit::alpha_test};
              c.regs.TEST_1 = {ate, static_cast<gs::atst>(atst), gs::u8::from_wrapped(aref),
                               static_cast<gs::afail>(afail)};
              c.regs.FRAME_1.PSM = psm;
              c.options.rgb_only = rgb_only;
              b.run(c);
              wrong += compare(
                  b, 1,
                  [&](const block& k, std::size_t i) -> std::array<std::int32_t, 3> {
                    const gs::write_enables w =
                        gs::alpha_test(c.regs.TEST_1, gs::u8::from_wrapped(k.in[0][i]), psm, c.options);
                    return {(w.rgb ? 1 : 0) | (w.a ? 2 : 0) | (w.z ? 4 : 0)};
                  },
                  "alpha_test");
              seen += 256;
            }
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(seen, std::size_t{1} << 26);
}

// dither: a blend output (s11, 2^11) × the pixel's place in the 4×4 matrix (16) × its 3-bit DIMX
// entry (8: the eight matrices DM[i][j] = (4i + j + k) & 7 put every entry at every place) ×
// dither_decode (3) × DTHE (2) × pixel_bits of FRAME.PSM (3 formats: PSMCT32, PSMCT24, PSMCT16) ×
// dither_targets (2) = 2^11 · 16 · 8 · 3 · 2 · 3 · 2 = 9 437 184; and dither_value's 8 × 3.
TEST(SimdExhaustive, DitherOverEveryValuePlaceEntryAndOption) {
  block b(2048 * 16);
  for (std::size_t i = 0; i < b.n; ++i) {
    const std::int32_t v = static_cast<std::int32_t>(i % 2048) - 1024;
    b.in[0][i] = v, b.in[1][i] = -v - 1, b.in[2][i] = v / 2;
    b.in[3][i] = static_cast<std::int32_t>((i / 2048) % 4), b.in[4][i] = static_cast<std::int32_t>((i / 2048) / 4);
  }
  std::size_t wrong = 0;
  for (int k = 0; k < 8; ++k)
    for (const auto decode :
         {gs::dither_decode::twos_complement, gs::dither_decode::sign_magnitude, gs::dither_decode::inverted_magnitude})
      for (bool dthe : {false, true})
        for (const gs::frame_psm psm : {gs::frame_psm::PSMCT32, gs::frame_psm::PSMCT24, gs::frame_psm::PSMCT16})
          for (const auto on : {gs::dither_targets::sixteen_bit_only, gs::dither_targets::all_formats}) {
            unit_call c{unit::dither};
            for (std::size_t i = 0; i < 4; ++i)
              for (std::size_t j = 0; j < 4; ++j)
                c.regs.DIMX.DM[i][j] = gs::u3::from_wrapped(static_cast<int>(4 * i + j) + k);
            c.regs.DTHE.DTHE = dthe, c.regs.FRAME_1.PSM = psm;
            c.options.dither = decode, c.options.dither_on = on;
            b.run(c);
            wrong += compare(
                b, 3,
                [&](const block& t, std::size_t i) -> std::array<std::int32_t, 3> {
                  const gs::rgb_wide in{gs::s11::from_wrapped(t.in[0][i]), gs::s11::from_wrapped(t.in[1][i]),
                                        gs::s11::from_wrapped(t.in[2][i])};
                  const gs::rgb_wide r = gs::dither(in, c.regs.DIMX, static_cast<unsigned>(t.in[3][i]),
                                                    static_cast<unsigned>(t.in[4][i]), dthe, psm, c.options);
                  return {r.r.value(), r.g.value(), r.b.value()};
                },
                "dither");
          }
  block d(16);
  for (std::size_t i = 0; i < 16; ++i) d.in[0][i] = static_cast<std::int32_t>(i % 8);
  for (const auto decode :
       {gs::dither_decode::twos_complement, gs::dither_decode::sign_magnitude, gs::dither_decode::inverted_magnitude}) {
    unit_call c{unit::dither_value};
    c.options.dither = decode;
    d.run(c);
    wrong += compare(
        d, 1,
        [&](const block& t, std::size_t i) -> std::array<std::int32_t, 3> {
          return {gs::dither_value(gs::u3::from_wrapped(t.in[0][i]), decode).value()};
        },
        "dither_value");
  }
  EXPECT_EQ(wrong, 0u);
}

// colclamp: every s11 value (2^11) × CLAMP (2) = 4096.
TEST(SimdExhaustive, ColclampOverEveryWideValue) {
  block b(2048);
  for (std::size_t i = 0; i < 2048; ++i) b.in[0][i] = static_cast<std::int32_t>(i) - 1024;
  std::size_t wrong = 0;
  for (bool clamp : {false, true}) {
    unit_call c{unit::colclamp};
    c.regs.COLCLAMP.CLAMP = clamp;
    b.run(c);
    wrong += compare(
        b, 1,
        [&](const block& t, std::size_t i) -> std::array<std::int32_t, 3> {
          return {gs::colclamp_channel(gs::s11::from_wrapped(t.in[0][i]), clamp).value()};
        },
        "colclamp");
  }
  EXPECT_EQ(wrong, 0u);
}

// blend_channel: a, b, c, d (2^8 each) = 2^32 per blend_shift value (one shard per value).
class BlendChannel : public ::testing::TestWithParam<gs::blend_shift> {};
TEST_P(BlendChannel, OverEveryOperandQuadruple) {
  const gs::blend_shift shift = GetParam();
  block b(lanes);
  for (std::size_t i = 0; i < lanes; ++i)
    b.in[2][i] = static_cast<std::int32_t>(i & 0xFF), b.in[3][i] = static_cast<std::int32_t>(i >> 8);
  unit_call c{unit::blend_channel};
  c.options.shift = shift;
  std::size_t wrong = 0, seen = 0;
  for (int a = 0; a < 256; ++a)
    for (int bb = 0; bb < 256; ++bb) {
      std::fill(b.in[0].begin(), b.in[0].end(), a);
      std::fill(b.in[1].begin(), b.in[1].end(), bb);
      b.run(c);
      const auto ua = gs::u8::from_wrapped(a), ub = gs::u8::from_wrapped(bb);
      for (std::size_t i = 0; i < lanes; ++i) {
        const std::int32_t e = gs::blend_channel(ua, ub, gs::u8::from_wrapped(static_cast<int>(i & 0xFF)),
                                                 gs::u8::from_wrapped(static_cast<int>(i >> 8)), shift)
                                   .value();
        if (b.out[0][i] != e && wrong++ < 3)
          ADD_FAILURE() << std::hex << "a 0x" << a << " b 0x" << bb << " c 0x" << (i & 0xFF) << " d 0x" << (i >> 8)
                        << ": SIMD 0x" << b.out[0][i] << ", scalar 0x" << e;
      }
      seen += lanes;
    }
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(seen, std::size_t{1} << 32);
}
INSTANTIATE_TEST_SUITE_P(Shift, BlendChannel, ::testing::Values(gs::blend_shift::floor, gs::blend_shift::truncate));

}  // namespace
}  // namespace gsdot3::simd::test

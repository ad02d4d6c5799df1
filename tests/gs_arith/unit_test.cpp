// gs_arith_unit — each GS unit against its closed-form expectation (reference.hpp), swept over
// register values (the Dolphin hwtests habit), plus register decode round trips and errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "gs_arith/alpha_blend.hpp"
#include "gs_arith/alpha_test.hpp"
#include "gs_arith/bilinear.hpp"
#include "gs_arith/clut.hpp"
#include "gs_arith/colclamp.hpp"
#include "gs_arith/dither.hpp"
#include "gs_arith/frame_write.hpp"
#include "gs_arith/gouraud.hpp"
#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/registers.hpp"
#include "gs_arith/texture_function.hpp"
#include "model_calls.hpp"
#include "reference.hpp"

namespace {

using gs::rgba8;
using gs::u8;

std::string hex(std::uint64_t v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%llx", static_cast<unsigned long long>(v));
  return buf;
}

using gs_test::u8v;
gs::gouraud_channel cf(int v87) { return gs::gouraud_channel::from_wrapped(v87); }

constexpr int sample_values[] = {0x00, 0x01, 0x3F, 0x40, 0x7F, 0x80, 0x81, 0xC0, 0xFE, 0xFF};
constexpr int sample_87[] = {0x0000, 0x0001, 0x007F, 0x0080, 0x2000, 0x3FFF, 0x4000, 0x4001, 0x7F80, 0x7FFF};

// ---------------------------------------------------------------- texture function
TEST(TextureFunction, AllModesAgainstTable) {
  for (int fn = 0; fn < 4; ++fn)
    for (int cc = 0; cc < 2; ++cc)
      for (bool keep : {true, false})
        for (int t : sample_values)
          for (int f : sample_87) {
            gs::model_options o;
            o.gouraud = keep ? gs::gouraud_fraction::keep_fraction : gs::gouraud_fraction::truncate_to_8;
            const std::uint32_t texel = gs_ref::word(t, 255 - t, t ^ 0x55, t);
            const gs::fragment_colour frag{cf(f), cf(0x7FFF - f), cf(f ^ 0x1555), cf(f)};
            const auto got = gs::texture_function(static_cast<gs::tfx>(fn), static_cast<gs::tcc>(cc),
                                                  rgba8::from_u32(texel), frag, o);
            const auto want = gs_ref::texture_function(fn, cc == 1, texel, {f, 0x7FFF - f, f ^ 0x1555, f}, keep);
            ASSERT_EQ(got.to_u32(), want) << "tfx " << fn << " tcc " << cc << " keep " << keep << " texel "
                                          << hex(texel) << " cf87 " << hex(static_cast<unsigned>(f));
          }
}

TEST(TextureFunction, OffPassesIntegerPart) {
  const gs::fragment_colour frag{cf(0x4000 + 0x7F), cf(0x7FFF), cf(0), cf(0x80)};
  EXPECT_EQ(gs::texture_off(frag).to_u32(), gs_ref::word(0x80, 0xFF, 0x00, 0x01));
}

// ---------------------------------------------------------------- alpha blend
TEST(AlphaBlend, All81ModesOnSampleColours) {
  const std::uint32_t pairs[][2] = {{0xffff00ff, 0xff00ff00},
                                    {0x40402040, 0x80204020},
                                    {0x00000000, 0xffffffff},
                                    {0x80ff80ff, 0x01020304},
                                    {0xfe7f0181, 0x7f80fe01}};
  for (int A = 0; A < 3; ++A)
    for (int B = 0; B < 3; ++B)
      for (int C = 0; C < 3; ++C)
        for (int D = 0; D < 3; ++D)
          for (const auto& p : pairs)
            for (int fix : sample_values)
              for (bool fl : {true, false}) {
                gs::model_options o;
                o.shift = fl ? gs::blend_shift::floor : gs::blend_shift::truncate;
                const gs::alpha_reg reg{static_cast<gs::blend_colour>(A), static_cast<gs::blend_colour>(B),
                                        static_cast<gs::blend_alpha>(C), static_cast<gs::blend_colour>(D), u8v(fix)};
                const auto got = gs::alpha_blend(reg, rgba8::from_u32(p[0]), rgba8::from_u32(p[1]), o);
                const auto want = gs_ref::alpha_blend(A, B, C, D, fix, p[0], p[1], fl);
                ASSERT_EQ(got.r.value(), want[0]) << A << B << C << D << " " << hex(p[0]) << " " << hex(p[1]);
                ASSERT_EQ(got.g.value(), want[1]);
                ASSERT_EQ(got.b.value(), want[2]);
              }
}

TEST(AlphaBlend, DigestExample) {
  // (Cs − Cd)·As + Cd, src ff402040, dst ff204020 -> ff5f005f (HW).
  const gs::alpha_reg reg{gs::blend_colour::Cs, gs::blend_colour::Cd, gs::blend_alpha::As, gs::blend_colour::Cd, u8{}};
  const auto wide = gs::alpha_blend(reg, rgba8::from_u32(0xff402040), rgba8::from_u32(0xff204020), {});
  EXPECT_EQ(gs::colclamp(wide, u8v(0xff), true).to_u32(), 0xff5f005fu);
}

TEST(AlphaBlend, RangeExtremes) {
  // −255·255 / 128 floors to −509 with D = 0; 255·255 / 128 + 255 = 763.
  EXPECT_EQ(gs::blend_channel(u8v(0), u8v(255), u8v(255), u8v(0), gs::blend_shift::floor).value(), -509);
  EXPECT_EQ(gs::blend_channel(u8v(0), u8v(255), u8v(255), u8v(0), gs::blend_shift::truncate).value(), -508);
  EXPECT_EQ(gs::blend_channel(u8v(255), u8v(0), u8v(255), u8v(255), gs::blend_shift::floor).value(), 763);
}

// ---------------------------------------------------------------- COLCLAMP
TEST(Colclamp, SweepWideRange) {
  for (int v = -1024; v < 1024; v += 7)
    for (bool clamp : {true, false})
      ASSERT_EQ(gs::colclamp_channel(gs::s11::from_wrapped(v), clamp).value(), gs_ref::colclamp(v, clamp)) << v;
}

// ---------------------------------------------------------------- alpha test
TEST(AlphaTest, MethodsAndFailModes) {
  const gs::frame_psm targets[] = {gs::frame_psm::PSMCT32, gs::frame_psm::PSMCT24, gs::frame_psm::PSMCT16,
                                   gs::frame_psm::PSMZ32};
  for (int method = 0; method < 8; ++method)
    for (int afail = 0; afail < 4; ++afail)
      for (bool ate : {false, true})
        for (int aref : sample_values)
          for (int a : sample_values)
            for (auto psm : targets) {
              const auto got = gs_test::alpha_test_of(ate, method, aref, afail, a, psm);
              const bool is32 = psm == gs::frame_psm::PSMCT32 || psm == gs::frame_psm::PSMZ32;
              const auto want = gs_ref::alpha_test(ate, method, aref, afail, a, is32);
              ASSERT_EQ(got.rgb, want[0]) << method << " " << afail << " " << aref << " " << a;
              ASSERT_EQ(got.a, want[1]) << method << " " << afail << " " << aref << " " << a;
              ASSERT_EQ(got.z, want[2]) << method << " " << afail << " " << aref << " " << a;
            }
}

TEST(AlphaTest, RgbOnlyAllFormatsKeepsAlphaEverywhere) {
  gs::model_options all;
  all.rgb_only = gs::rgb_only_targets::all_formats;
  for (auto psm : {gs::frame_psm::PSMCT32, gs::frame_psm::PSMCT24, gs::frame_psm::PSMCT16, gs::frame_psm::PSMZ16S})
    for (int afail = 0; afail < 4; ++afail)
      for (int a : sample_values) {
        const auto got = gs_test::alpha_test_of(true, 2, 0x80, afail, a, psm, all);  // LESS
        const auto want = gs_ref::alpha_test(true, 2, 0x80, afail, a, true);         // as on a 32-bit frame
        ASSERT_EQ(got.rgb, want[0]) << afail << " " << a;
        ASSERT_EQ(got.a, want[1]) << afail << " " << a;
        ASSERT_EQ(got.z, want[2]) << afail << " " << a;
      }
}

// ---------------------------------------------------------------- dither
TEST(Dither, DecodeInvertedMagnitude) {
  for (int dm = 0; dm < 8; ++dm)
    EXPECT_EQ(gs::dither_value(gs::u3::from_wrapped(dm), gs::dither_decode::inverted_magnitude).value(),
              gs_ref::dither_inverted_magnitude(dm));
}

// The DIMX programs commonly set (ps2dev forum: rows 4,2,5,3 / 0,6,1,7 / 5,3,4,2 / 1,7,0,6) under each
// decode, against the transposed 4x4 Bayer offsets floor(B / 2) − 4 written out by hand.
TEST(Dither, CommonMatrixIsBayerOnlyAsTwosComplement) {
  const int dimx[4][4] = {{4, 2, 5, 3}, {0, 6, 1, 7}, {5, 3, 4, 2}, {1, 7, 0, 6}};
  const int bayer_t[4][4] = {{-4, 2, -3, 3}, {0, -2, 1, -1}, {-3, 3, -4, 2}, {1, -1, 0, -2}};
  auto matches = [&](gs::dither_decode d) {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (gs::dither_value(gs::u3::from_wrapped(dimx[i][j]), d).value() != bayer_t[i][j]) return false;
    return true;
  };
  EXPECT_TRUE(matches(gs::dither_decode::twos_complement));
  EXPECT_FALSE(matches(gs::dither_decode::sign_magnitude));
  EXPECT_FALSE(matches(gs::dither_decode::inverted_magnitude));
}

TEST(Dither, DecodeBothOptions) {
  for (int dm = 0; dm < 8; ++dm) {
    EXPECT_EQ(gs::dither_value(gs::u3::from_wrapped(dm), gs::dither_decode::twos_complement).value(),
              gs_ref::dither_twos(dm));
    EXPECT_EQ(gs::dither_value(gs::u3::from_wrapped(dm), gs::dither_decode::sign_magnitude).value(),
              gs_ref::dither_sign_magnitude(dm));
  }
}

TEST(Dither, MatrixPositionAndTargets) {
  const gs::dimx_reg dimx = gs::decode_dimx(0x0123456701234567ull);  // DM[i][j] = value at bits 16i + 4j
  for (unsigned y = 0; y < 8; ++y)
    for (unsigned x = 0; x < 8; ++x)
      for (auto psm : {gs::frame_psm::PSMCT16, gs::frame_psm::PSMCT32})
        for (auto targets : {gs::dither_targets::sixteen_bit_only, gs::dither_targets::all_formats})
          for (bool dthe : {false, true}) {
            gs::model_options o;
            o.dither_on = targets;
            const gs::rgb_wide in{gs::s11::from_wrapped(100), gs::s11::from_wrapped(-3), gs::s11::from_wrapped(300)};
            const auto out = gs::dither(in, dimx, x, y, dthe, psm, o);
            const int nibble = static_cast<int>((0x0123456701234567ull >> (16 * (y % 4) + 4 * (x % 4))) & 0xF) % 8;
            const bool on = dthe && (psm == gs::frame_psm::PSMCT16 || targets == gs::dither_targets::all_formats);
            const int d = on ? gs_ref::dither_twos(nibble) : 0;
            ASSERT_EQ(out.r.value(), 100 + d) << x << "," << y;
            ASSERT_EQ(out.g.value(), -3 + d);
            ASSERT_EQ(out.b.value(), 300 + d);
          }
}

// ---------------------------------------------------------------- frame write
TEST(FrameWrite, Pack16AndRead16) {
  for (std::uint32_t c : {0x00000000u, 0xffffffffu, 0x80f8f8f8u, 0x7f070707u, 0x12345678u, 0x80808080u}) {
    EXPECT_EQ(gs::frame_pack(gs::frame_psm::PSMCT16, rgba8::from_u32(c)), gs_ref::pack16(c)) << hex(c);
    EXPECT_EQ(gs::frame_read(gs::frame_psm::PSMCT16, gs_ref::pack16(c)).to_u32(), gs_ref::read16(gs_ref::pack16(c)));
  }
}

TEST(FrameWrite, TwentyFourBitTarget) {
  // The blender reads Ad as 0x80; the top byte of memory is never written, FBA does not apply.
  EXPECT_EQ(gs::frame_read(gs::frame_psm::PSMCT24, 0x11223344u).to_u32(), 0x80223344u);
  EXPECT_EQ(gs::frame_write(gs::frame_psm::PSMCT24,
                            gs::apply_fba(rgba8::from_u32(0x00aabbccu), true, gs::frame_psm::PSMCT24), 0x11223344u, 0),
            0x11aabbccu);
}

TEST(FrameWrite, FbmskMergeAndFba) {
  for (std::uint32_t mask : {0u, 0xffffffffu, 0xffffff00u, 0x00ff00ffu, 0x80000000u})
    for (std::uint32_t old : {0u, 0xdeadbeefu}) {
      const rgba8 c = rgba8::from_u32(0x01234567u);
      EXPECT_EQ(gs::frame_write(gs::frame_psm::PSMCT32, c, old, mask), gs_ref::merge(0x01234567u, old, mask));
      EXPECT_EQ(gs::frame_write(gs::frame_psm::PSMCT16, c, old & 0xffffu, mask),
                gs_ref::merge(gs_ref::pack16(0x01234567u), old & 0xffffu, gs_ref::pack16(mask) | 0xffff0000u));
    }
  EXPECT_EQ(gs::apply_fba(rgba8::from_u32(0x00000000u), true, gs::frame_psm::PSMCT32).to_u32(), 0x80000000u);
  EXPECT_EQ(gs::apply_fba(rgba8::from_u32(0x7f000000u), true, gs::frame_psm::PSMCT16).to_u32(), 0xff000000u);
  EXPECT_EQ(gs::apply_fba(rgba8::from_u32(0x7f000000u), false, gs::frame_psm::PSMCT32).to_u32(), 0x7f000000u);
}

// ---------------------------------------------------------------- Gouraud
TEST(Gouraud, SpanGradientAndEndpoints) {
  for (int c0 : sample_values)
    for (int c1 : sample_values)
      for (int n : {1, 2, 3, 7, 16, 100, 640}) {
        const auto step = gs::gouraud_gradient(u8v(c0), u8v(c1), n);
        ASSERT_EQ(step.value(), gs_ref::gradient(c0, c1, n)) << c0 << " " << c1 << " " << n;
        const auto span = gs::gouraud_span(rgba8::from_u32(gs_ref::word(c0, c1, c0, c1)),
                                           rgba8::from_u32(gs_ref::word(c1, c0, c1, c0)), n);
        for (int k : {0, 1, n / 2, n}) {
          const long long want = static_cast<long long>(c0) * 128 + k * gs_ref::gradient(c0, c1, n);
          ASSERT_EQ(gs::gouraud_at(span, k).r.value(), want) << c0 << " " << c1 << " " << n << " " << k;
        }
        // The truncated step never overshoots: at k = n the value lies between c0 and c1 (·128).
        const long long end = gs::gouraud_at(span, n).r.value();
        ASSERT_LE(std::min(c0, c1) * 128, end);
        ASSERT_LE(end, std::max(c0, c1) * 128);
      }
}

TEST(Gouraud, ClampAtZeroAndTop) {
  EXPECT_EQ(gs::gouraud_at(gs::gouraud_start::from_wrapped(100), gs::gouraud_step::from_wrapped(-60), 2).value(), 0);
  EXPECT_EQ(gs::gouraud_at(gs::gouraud_start::from_wrapped(0x7F00), gs::gouraud_step::from_wrapped(0x100), 3).value(),
            0x7FFF);
}

TEST(Gouraud, TrianglePlaneThroughPixelAlignedVertices) {
  // Vertices on pixel centres, 16 pixels apart: the gradients are exact multiples, so the plane
  // reproduces each vertex colour exactly at its pixel.
  const gs::gouraud_vertex v0{16 * 10, 16 * 20, rgba8::from_u32(0x80000000u)};
  const gs::gouraud_vertex v1{16 * 26, 16 * 20, rgba8::from_u32(0x80000080u)};
  const gs::gouraud_vertex v2{16 * 10, 16 * 36, rgba8::from_u32(0x80008000u)};
  const auto plane = gs::gouraud_triangle(v0, v1, v2, 10, 20);
  ASSERT_TRUE(plane.has_value());
  EXPECT_EQ(gs::gouraud_at(*plane, 10, 20), gs::fragment_colour::flat(v0.c));
  EXPECT_EQ(gs::gouraud_at(*plane, 26, 20), gs::fragment_colour::flat(v1.c));
  EXPECT_EQ(gs::gouraud_at(*plane, 10, 36), gs::fragment_colour::flat(v2.c));
  EXPECT_EQ(gs::gouraud_at(*plane, 18, 28).r.value(), 0x80 * 128 / 2);  // halfway along x: 0x40.00
  EXPECT_EQ(gs::gouraud_at(*plane, 18, 28).g.value(), 0x80 * 128 / 2);
  EXPECT_FALSE(gs::gouraud_triangle(v0, v0, v2, 10, 20).has_value());
}

TEST(Gouraud, FlatTakesLastVertex) { EXPECT_EQ(gs::flat_shading(rgba8::from_u32(0x11223344u)).g.value(), 0x33 * 128); }

// ---------------------------------------------------------------- bilinear
TEST(Bilinear, Lerp16_4Sweep) {
  for (int c0 : sample_values)
    for (int c1 : sample_values)
      for (int w = 0; w < 16; ++w)
        ASSERT_EQ(gs::lerp16_4(u8v(c0), u8v(c1), gs::u4::from_wrapped(w)).value(), gs_ref::lerp16_4(c0, c1, w));
}

TEST(Bilinear, FootprintSubtractsHalfTexel) {
  // u = 2.5 texels (12.4: 40): lerp16_4 -> texels 2..3 with weight 0; u = 2.0 -> texels 1..2, weight 8.
  EXPECT_EQ(gs::footprint(40, 32, gs::bilinear_mode::lerp16_4),
            (gs::texel_footprint{2, 1, gs::u4::from_wrapped(0), gs::u4::from_wrapped(8)}));
  EXPECT_EQ(gs::footprint(0, 3, gs::bilinear_mode::lerp16_4),
            (gs::texel_footprint{-1, -1, gs::u4::from_wrapped(8), gs::u4::from_wrapped(11)}));
  EXPECT_EQ(gs::footprint(40, 31, gs::bilinear_mode::nearest), (gs::texel_footprint{2, 1, gs::u4{}, gs::u4{}}));
}

TEST(Bilinear, FilterHorizontalThenVertical) {
  const std::uint32_t t[4] = {0x00000000u, 0xff102030u, 0x80ffffffu, 0x01020304u};
  for (int wu = 0; wu < 16; wu += 5)
    for (int wv = 0; wv < 16; wv += 3) {
      const auto got = gs::bilinear_filter(rgba8::from_u32(t[0]), rgba8::from_u32(t[1]), rgba8::from_u32(t[2]),
                                           rgba8::from_u32(t[3]), gs::u4::from_wrapped(wu), gs::u4::from_wrapped(wv));
      for (int ch = 0; ch < 4; ++ch) {
        const int top = gs_ref::lerp16_4(gs_ref::byte(t[0], ch), gs_ref::byte(t[1], ch), wu);
        const int bottom = gs_ref::lerp16_4(gs_ref::byte(t[2], ch), gs_ref::byte(t[3], ch), wu);
        ASSERT_EQ(gs_ref::byte(got.to_u32(), ch), gs_ref::lerp16_4(top, bottom, wv)) << wu << " " << wv << " " << ch;
      }
    }
}

TEST(Bilinear, WeightedSum4IsTheDoubleSumTruncated) {
  for (int wu = 0; wu < 16; ++wu)
    for (int wv = 0; wv < 16; ++wv)
      for (int t00 : sample_values)
        for (int t11 : sample_values) {
          const int t10 = 255 - t00, t01 = (t00 + t11) / 2;
          const auto got = gs::weighted_sum_4(u8v(t00), u8v(t10), u8v(t01), u8v(t11), gs::u4::from_wrapped(wu),
                                              gs::u4::from_wrapped(wv));
          ASSERT_EQ(got.value(), gs_ref::weighted_sum_4(t00, t10, t01, t11, wu, wv)) << wu << " " << wv;
        }
}

TEST(Bilinear, SampleWeightedSum4UsesTheLerpFootprint) {
  auto fetch = [](std::int32_t u, std::int32_t v) {
    return rgba8::from_u32(static_cast<std::uint32_t>(u * 40 + v * 3));
  };
  // u = 3 + 15/16 + 1/2 texels: footprint u0 = 3, wu = 15 (as lerp16_4); v = 5.5: v0 = 5, wv = 0.
  const auto got = gs::sample(fetch, 16 * 3 + 15 + 8, 16 * 5 + 8, gs::bilinear_mode::weighted_sum_4);
  const int want = gs_ref::weighted_sum_4(3 * 40 + 15, 4 * 40 + 15, 3 * 40 + 18, 4 * 40 + 18, 15, 0);
  EXPECT_EQ(gs_ref::byte(got.to_u32(), 0), want);
}

TEST(Bilinear, SampleNearestIgnoresNeighbours) {
  auto fetch = [](std::int32_t u, std::int32_t v) { return rgba8::from_u32(static_cast<std::uint32_t>(u * 16 + v)); };
  EXPECT_EQ(gs::sample(fetch, 16 * 3 + 15, 16 * 5, gs::bilinear_mode::nearest).to_u32(), 3u * 16 + 5);
}

// ---------------------------------------------------------------- CLUT
TEST(Clut, Csm1PositionMatchesPcsx2Derivation) {
  // PCSX2 GSClut.cpp WriteCLUT_T32_I8_CSM1 reads entry group g (16 entries) from word offset
  // clutTableT32I8[(g << 4) & 0x70] | ((g << 4) & 0x80): 0, 64, 16, 80, 32, 96, 48, 112 (+128 for g >= 8).
  // In a PSMCT32 block (8×8 pixels, 64 words), words 16k .. 16k + 15 are rows 2k, 2k + 1; the block
  // at word 64 is the one to the right (blockTable32[0][1] = 1), the next 128 words the 8 rows below.
  const int group_word[8] = {0, 64, 16, 80, 32, 96, 48, 112};
  for (int i = 0; i < 256; ++i) {
    const int g = i / 16;
    const int w = group_word[g % 8] + 128 * (g / 8);
    const int block = w / 64, in_block = w % 64;
    const int x = 8 * (block % 2) + i % 8;
    const int y = 8 * (block / 2) + in_block / 8 + (i % 16) / 8;
    ASSERT_EQ(static_cast<int>(gs::csm1_position(u8v(i))), 16 * y + x) << i;
    ASSERT_EQ(static_cast<int>(gs::csm1_position(u8v(i))), gs_ref::csm1_position(i)) << i;
  }
}

TEST(Clut, LookupT8T4T8H) {
  std::array<rgba8, 256> image{};
  for (int p = 0; p < 256; ++p)
    image[static_cast<std::size_t>(p)] = rgba8::from_u32(0xff000000u | static_cast<std::uint32_t>(p));
  const auto buf = gs::load_csm1_t8(image);
  for (int i = 0; i < 256; ++i)
    ASSERT_EQ(gs::clut_t8(buf, u8v(i)).to_u32() & 0xffu, static_cast<std::uint32_t>(gs_ref::csm1_position(i)));
  EXPECT_EQ(gs::clut_t8(buf, u8v(8)).to_u32(), 0xff000010u);  // entry 8: row 1, column 0
  EXPECT_EQ(gs::t8h_index(0x17aabbccu).value(), 0x17);

  std::array<rgba8, 16> small{};
  for (int p = 0; p < 16; ++p)
    small[static_cast<std::size_t>(p)] = rgba8::from_u32(0x11000000u + static_cast<std::uint32_t>(p));
  const auto buf4 = gs::load_csm1_t4(buf, small, gs::u5::from_wrapped(3));
  for (int i = 0; i < 16; ++i) {
    EXPECT_EQ(gs::clut_t4(buf4, gs::u4::from_wrapped(i), gs::u5::from_wrapped(3)).to_u32(),
              0x11000000u + static_cast<std::uint32_t>(i));
    EXPECT_EQ(gs::clut_t4(buf4, gs::u4::from_wrapped(i), gs::u5::from_wrapped(0)), buf[static_cast<std::size_t>(i)]);
  }
  // PSMT8 with CSA: group offset clamps at entry 240 (PCSX2 ReadCLUT_T32_I8).
  EXPECT_EQ(gs::clut_t8(buf, u8v(0xF5), gs::u5::from_wrapped(1)), buf[0xF5]);
  EXPECT_EQ(gs::clut_t8(buf, u8v(0x05), gs::u5::from_wrapped(1)), buf[0x15]);
}

// ---------------------------------------------------------------- registers
TEST(Registers, DecodeKnownValues) {
  // Hand-assembled from the manual layout.
  const auto prim = gs::decode_prim(0x6 | 1 << 3 | 1 << 4 | 1 << 6 | 1 << 10);
  EXPECT_EQ(prim.PRIM, gs::prim_type::SPRITE);
  EXPECT_TRUE(prim.IIP && prim.TME && prim.ABE && prim.FIX);
  EXPECT_FALSE(prim.FGE || prim.AA1 || prim.FST || prim.CTXT);

  const auto alpha = gs::decode_alpha(0x80ull << 32 | 2u << 6 | 2u << 4 | 1u << 2 | 0u);
  EXPECT_EQ(alpha, (gs::alpha_reg{gs::blend_colour::Cs, gs::blend_colour::Cd, gs::blend_alpha::FIX,
                                  gs::blend_colour::zero, u8v(0x80)}));

  const std::uint64_t tex0 = 0x1234 | 5ull << 14 | 0x13ull << 20 | 8ull << 26 | 7ull << 30 | 1ull << 34 | 3ull << 35 |
                             0x2abcull << 37 | 0xAull << 51 | 1ull << 55 | 17ull << 56 | 4ull << 61;
  const auto t = gs::decode_tex0(tex0);
  EXPECT_EQ(t.TBP0.value(), 0x1234);
  EXPECT_EQ(t.TBW.value(), 5);
  EXPECT_EQ(t.PSM, gs::tex_psm::PSMT8);
  EXPECT_EQ(t.TW.value(), 8);
  EXPECT_EQ(t.TH.value(), 7);
  EXPECT_EQ(t.TCC, gs::tcc::RGBA);
  EXPECT_EQ(t.TFX, gs::tfx::HIGHLIGHT2);
  EXPECT_EQ(t.CBP.value(), 0x2abc);
  EXPECT_EQ(t.CPSM, gs::clut_psm::PSMCT16S);
  EXPECT_TRUE(t.CSM);
  EXPECT_EQ(t.CSA.value(), 17);
  EXPECT_EQ(t.CLD.value(), 4);
  EXPECT_EQ(gs::encode(t), tex0);

  const auto test = gs::decode_test(1 | 6u << 1 | 0x80u << 4 | 3u << 12 | 1u << 16 | 2u << 17);
  EXPECT_TRUE(test.ATE);
  EXPECT_EQ(test.ATST, gs::atst::GREATER);
  EXPECT_EQ(test.AREF.value(), 0x80);
  EXPECT_EQ(test.AFAIL, gs::afail::RGB_ONLY);
  EXPECT_TRUE(test.ZTE);
  EXPECT_EQ(test.ZTST, gs::ztst::GEQUAL);

  const auto frame = gs::decode_frame(0xffffff00ull << 32 | 0x02ull << 24 | 10ull << 16 | 0x1ff);
  EXPECT_EQ(frame.FBP.value(), 0x1ff);
  EXPECT_EQ(frame.FBW.value(), 10);
  EXPECT_EQ(frame.PSM, gs::frame_psm::PSMCT16);
  EXPECT_EQ(frame.FBMSK, 0xffffff00u);

  const auto dimx = gs::decode_dimx(0x7000000000000004ull);
  EXPECT_EQ(dimx.DM[0][1].value(), 0);
  EXPECT_EQ(dimx.DM[0][0].value(), 4);
  EXPECT_EQ(dimx.DM[3][3].value(), 7);

  const auto rgbaq = gs::decode_rgbaq(0x3f800000ull << 32 | 0x80402010u);
  EXPECT_EQ(rgbaq.colour.to_u32(), 0x80402010u);
  EXPECT_EQ(rgbaq.Q, 0x3f800000u);
}

TEST(Registers, RoundTripThroughNames) {
  const std::pair<const char*, std::uint64_t> values[] = {{"PRIM", 0x7fe},
                                                          {"RGBAQ", 0xfedcba9876543210ull},
                                                          {"TEX0_1", 0xff92aab6694fffffull},
                                                          {"ALPHA_1", 0xab000000a6ull},
                                                          {"TEST_1", 0x7ffff},
                                                          {"FRAME_1", 0x123456783a3f01ffull},
                                                          {"COLCLAMP", 0},
                                                          {"PABE", 1},
                                                          {"FBA_1", 1},
                                                          {"DTHE", 1},
                                                          {"DIMX", 0x7777777777777777ull}};
  for (const auto& [name, v] : values) {
    gs::gs_registers regs;
    gs::set_register(regs, name, v);
    EXPECT_EQ(gs::register_value(regs, name), v) << name << " " << hex(v);
  }
}

TEST(Registers, NeutralDefaultsAreZeroExceptColclamp) {
  const gs::gs_registers regs;
  for (auto name : gs::register_names) EXPECT_EQ(gs::register_value(regs, name), name == "COLCLAMP" ? 1u : 0u) << name;
}

TEST(Registers, ReservedValuesThrow) {
  const std::pair<const char*, std::uint64_t> bad[] = {{"ALPHA_1", 3},
                                                       {"ALPHA_1", 3 << 2},
                                                       {"ALPHA_1", 3 << 4},
                                                       {"ALPHA_1", 3 << 6},
                                                       {"ALPHA_1", 1ull << 40},
                                                       {"ALPHA_1", 1ull << 8},
                                                       {"PRIM", 7},
                                                       {"PRIM", 1 << 11},
                                                       {"TEX0_1", 0x15ull << 20},
                                                       {"TEX0_1", 11ull << 26},
                                                       {"TEX0_1", 11ull << 30},
                                                       {"TEX0_1", 1ull << 51},
                                                       {"TEST_1", 1 << 19},
                                                       {"FRAME_1", 0x13ull << 24},
                                                       {"FRAME_1", 1 << 9},
                                                       {"COLCLAMP", 2},
                                                       {"PABE", 1ull << 63},
                                                       {"FBA_1", 2},
                                                       {"DTHE", 2},
                                                       {"DIMX", 8},
                                                       {"DIMX", 1ull << 63}};
  for (const auto& [name, v] : bad) {
    gs::gs_registers regs;
    EXPECT_THROW(gs::set_register(regs, name, v), gs::register_error) << name << " " << hex(v);
  }
  gs::gs_registers regs;
  EXPECT_THROW(gs::set_register(regs, "ALPHA_2", 0), gs::register_error);
  try {
    gs::set_register(regs, "ALPHA_1", 0x30);
    FAIL() << "no error for ALPHA_1.C = 3";
  } catch (const gs::register_error& e) {
    EXPECT_NE(std::string(e.what()).find("ALPHA_1.C"), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------- pixel pipeline scenarios
gs::pixel_trace run(const gs::gs_registers& regs, std::uint32_t vertex, std::uint32_t texel, std::uint32_t dst,
                    unsigned x = 0, unsigned y = 0, gs::model_options o = {}) {
  return gs::pixel_pipeline(regs,
                            {gs::fragment_colour::flat(rgba8::from_u32(vertex)), rgba8::from_u32(texel), dst, x, y}, o);
}

TEST(PixelPipeline, RedOnlyPassWithFbmsk) {
  gs::gs_registers regs;
  gs::set_register(regs, "FRAME_1", 0xffffff00ull << 32);
  EXPECT_EQ(run(regs, 0x11223344u, 0, 0xaabbccddu).out, 0xaabbcc44u);
}

TEST(PixelPipeline, TwentyFourBitBlendReadsAd0x80) {
  gs::gs_registers regs;
  gs::set_register(regs, "PRIM", 1 << 6);
  gs::set_register(regs, "ALPHA_1", 2u << 6 | 1u << 4 | 2u << 2 | 0u);  // (Cs − 0)·Ad + 0
  gs::set_register(regs, "FRAME_1", 0x01ull << 24);                     // PSMCT24
  // Ad reads as 0x80, so Cs passes unchanged; the top byte of memory (0x33) is kept.
  EXPECT_EQ(run(regs, 0x00405060u, 0, 0x33000000u).out, 0x33405060u);
}

TEST(PixelPipeline, SixteenBitDitherWrapAndFba) {
  gs::gs_registers regs;
  gs::set_register(regs, "FRAME_1", 0x02ull << 24);
  gs::set_register(regs, "DTHE", 1);
  gs::set_register(regs, "DIMX", 0x4000);  // DM03 = 4: −4 at x & 3 = 3, y & 3 = 0
  gs::set_register(regs, "COLCLAMP", 0);
  gs::set_register(regs, "FBA_1", 1);
  // R = 2 − 4 = −2 wraps to 254 -> 31; G 0x10 − 4 = 12 -> 1; B 0x81 − 4 = 125 -> 15; A bit 7 from FBA.
  EXPECT_EQ(run(regs, 0x00811002u, 0, 0, 3, 4).out, gs_ref::pack16(gs_ref::word(254, 12, 125, 0x80)));
  EXPECT_EQ(run(regs, 0x00811002u, 0, 0, 2, 4).out, gs_ref::pack16(gs_ref::word(2, 0x10, 0x81, 0x80)));
}

TEST(PixelPipeline, AlphaTestRgbOnlyKeepsAlpha) {
  gs::gs_registers regs;
  gs::set_register(regs, "TEST_1", 1 | 0u << 1 | 3u << 12);  // ATE, NEVER, RGB_ONLY
  EXPECT_EQ(run(regs, 0x11223344u, 0, 0xaabbccddu).out, 0xaa223344u);
  gs::set_register(regs, "TEST_1", 1 | 0u << 1 | 0u << 12);  // KEEP
  EXPECT_EQ(run(regs, 0x11223344u, 0, 0xaabbccddu).out, 0xaabbccddu);
}

TEST(PixelPipeline, PabeSkipsBlendForLowAlpha) {
  gs::gs_registers regs;
  gs::set_register(regs, "PRIM", 1 << 6);
  gs::set_register(regs, "ALPHA_1", 2u << 6 | 2u << 4 | 2u << 2 | 2u);  // (0 − 0)·FIX + 0 = black
  gs::set_register(regs, "PABE", 1);
  EXPECT_EQ(run(regs, 0x7f123456u, 0, 0).out, 0x7f123456u);
  EXPECT_EQ(run(regs, 0x80123456u, 0, 0).out, 0x80000000u);
}

TEST(PixelPipeline, TextureModulate) {
  gs::gs_registers regs;
  gs::set_register(regs, "PRIM", 1 << 4);
  gs::set_register(regs, "TEX0_1", 1ull << 34);  // MODULATE, TCC = RGBA
  EXPECT_EQ(run(regs, 0x80408000u, 0xff80ff40u, 0).out,
            gs_ref::texture_function(0, true, 0xff80ff40u, {0, 0x80 * 128, 0x40 * 128, 0x80 * 128}, true));
}

}  // namespace

// Drawing through the packet interpreter: small frames whose pixels are worked out by hand (the
// register bit layouts of the GS User's Manual written out here, pixel sets from the fill rule by
// hand, the CSM1 CLUT order as "bits 3 and 4 of the index swapped"), and a Gouraud triangle checked
// against gs::gouraud_triangle evaluated at each pixel the readable fill predicate gs::covers accepts.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <utility>
#include <vector>

#include "gs_arith/gouraud.hpp"
#include "gs_arith/rasteriser.hpp"
#include "gs_packets/builder.hpp"
#include "gs_packets/decoder.hpp"
#include "gs_packets/display.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/interpreter.hpp"
#include "gs_packets/state.hpp"

namespace {

using namespace gs::packets;
namespace mem = gs::mem;
using writes = std::vector<std::pair<std::uint8_t, std::uint64_t>>;

// Register values from the manual's bit layouts.
constexpr std::uint64_t frame(std::uint64_t fbp, std::uint64_t fbw, std::uint64_t psm = 0, std::uint64_t fbmsk = 0) {
  return fbp | fbw << 16 | psm << 24 | fbmsk << 32;
}
constexpr std::uint64_t scissor(std::uint64_t x0, std::uint64_t x1, std::uint64_t y0, std::uint64_t y1) {
  return x0 | x1 << 16 | y0 << 32 | y1 << 48;
}
constexpr std::uint64_t xyz(std::uint64_t x16, std::uint64_t y16, std::uint64_t z = 0) {
  return x16 | y16 << 16 | z << 32;
}
constexpr std::uint64_t rgbaq(std::uint64_t r, std::uint64_t g, std::uint64_t b, std::uint64_t a) {
  return r | g << 8 | b << 16 | a << 24 | std::uint64_t{0x3F800000} << 32;
}
constexpr std::uint64_t SPRITE = 6, TRIANGLE = 3, STRIP = 4, FAN = 5, IIP = 1 << 3, TME = 1 << 4, FGE = 1 << 5,
                        AA1 = 1 << 7, FST = 1 << 8, CTXT = 1 << 9;
constexpr std::uint8_t PRIM = 0x00, RGBAQ = 0x01, UV = 0x03, XYZ2 = 0x05, XYZ3 = 0x0D, TEX0_1 = 0x06, TEX1_1 = 0x14,
                       XYOFFSET_1 = 0x18, XYOFFSET_2 = 0x19, PRMODECONT = 0x1A, PRMODE = 0x1B, SCISSOR_1 = 0x40,
                       SCISSOR_2 = 0x41, COLCLAMP = 0x46, TEST_1 = 0x47, FRAME_1 = 0x4C, FRAME_2 = 0x4D, ZBUF_1 = 0x4E;

const mem::buffer fb0{fixed::uint<14>::from_wrapped(0), fixed::uint<6>::from_wrapped(1), mem::psm::PSMCT32};

// CSM1 stores a 256-entry CLUT with entries 8..15 and 16..23 of every 32 swapped (GS User's Manual,
// CLUT buffer; PCSX2's clutTableT32I8): raster position = index with bits 3 and 4 exchanged.
constexpr unsigned csm1_raster(unsigned i) { return (i & ~0x18u) | ((i & 0x08u) << 1) | ((i & 0x10u) >> 1); }
constexpr std::uint32_t clut_word(unsigned p) { return 0x80000000u | (p << 16) | ((255u - p) << 8) | p; }

void run(interpreter& it, const writes& w) {
  packet_builder pb;
  pb.ad(w, true);
  const auto bytes = pb.bytes();
  for (const gif_event& e : decode_gif(bytes)) it.apply(e, 16u * e.offset);
}

// Context 1 drawing into FBP 0, FBW 1 (64 pixels) PSMCT32, scissor 0..63, no Z test, COLCLAMP = 1.
writes environment() {
  return {{PRMODECONT, 1}, {COLCLAMP, 1}, {FRAME_1, frame(0, 1)}, {SCISSOR_1, scissor(0, 63, 0, 63)}, {TEST_1, 0}};
}

struct fixture {
  mem::local_memory m;
  interpreter it;
  explicit fixture(interpreter_options o = {}) : it(m, o) { run(it, environment()); }
  std::uint32_t px(int x, int y, const mem::buffer& b = fb0) const {
    return m.read_pixel(b, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
  }
  int count_nonzero(const mem::buffer& b = fb0) const {
    int n = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) n += px(x, y, b) != 0;
    return n;
  }
};

TEST(Draw, FlatSpriteFillsCeilOfItsCornersRightAndBottomExcluded) {
  fixture f;
  // Corners (1, 2) and (5, 4) pixels: columns 1..4, rows 2..3; colour 0x281E140A (A B G R).
  run(f.it, {{PRIM, SPRITE}, {RGBAQ, rgbaq(10, 20, 30, 40)}, {XYZ2, xyz(16, 32)}, {XYZ2, xyz(80, 64)}});
  for (int y = 2; y < 4; ++y)
    for (int x = 1; x < 5; ++x) EXPECT_EQ(f.px(x, y), 0x281E140Au) << x << "," << y;
  EXPECT_EQ(f.count_nonzero(), 8);
  EXPECT_EQ(f.it.pixels_drawn(), 8u);
  EXPECT_EQ(f.it.primitives_drawn(), 1u);
  // Half-pixel corners (1.5, 2.5) .. (3.5, 3.5): ceil gives columns 2..3, row 3.
  fixture g;
  run(g.it, {{PRIM, SPRITE}, {RGBAQ, rgbaq(1, 2, 3, 4)}, {XYZ2, xyz(24, 40)}, {XYZ2, xyz(56, 56)}});
  EXPECT_EQ(g.px(2, 3), 0x04030201u);
  EXPECT_EQ(g.px(3, 3), 0x04030201u);
  EXPECT_EQ(g.count_nonzero(), 2);
}

TEST(Draw, BitsOutsideTheFieldsAreIgnoredReservedFieldValuesNamed) {
  fixture f;
  // FRAME_1 with bits 9 and 22 set (between FBP / FBW / PSM: no field there) draws as FRAME_1 = FBP 0, FBW 1.
  run(f.it, {{FRAME_1, frame(0, 1) | 1 << 9 | 1 << 22},
             {PRIM, SPRITE},
             {RGBAQ, rgbaq(6, 6, 6, 6)},
             {XYZ2, xyz(0, 0)},
             {XYZ2, xyz(16, 16)}});
  EXPECT_EQ(f.px(0, 0), 0x06060606u);
  // ALPHA_1.A = 3 is reserved: the primitive is not drawn and the register is named.
  mem::local_memory m;
  interpreter it(m, {.skip_unmodelled = true});
  run(it, environment());
  run(it, {{0x42, 3}, {PRIM, SPRITE}, {XYZ2, xyz(0, 0)}, {XYZ2, xyz(16, 16)}});
  ASSERT_EQ(it.unmodelled_features().size(), 1u);
  EXPECT_EQ(it.unmodelled_features()[0].what.rfind("SPRITE: context 1 registers: ALPHA_1", 0), 0u)
      << it.unmodelled_features()[0].what;
}

// ZBUF_1 through gs_arith's decode_zbuf: bits outside ZBP (0-8), PSM (24-27), ZMSK (32) are dropped
// (PCSX2's ZBUF_REG_MASK 0x10F0001FF) and the Z buffer is still written at ZBP; PSM = 3 (no Z format)
// is refused and named.
TEST(Draw, ZbufBitsOutsideTheFieldsAreIgnoredAReservedPsmNamed) {
  fixture f;
  const mem::buffer zb{fixed::uint<14>::from_wrapped(16 * 32), fixed::uint<6>::from_wrapped(1), mem::psm::PSMZ32};
  const std::uint64_t always = 1 << 16 | 1 << 17;
  run(f.it, {{ZBUF_1, 16 | 1 << 9 | std::uint64_t{1} << 28 | std::uint64_t{1} << 40},
             {TEST_1, always},
             {PRIM, SPRITE},
             {RGBAQ, rgbaq(7, 7, 7, 7)},
             {XYZ2, xyz(0, 0, 321)},
             {XYZ2, xyz(16, 16, 321)}});
  EXPECT_EQ(f.px(0, 0), 0x07070707u);
  EXPECT_EQ(f.px(0, 0, zb), 321u);
  mem::local_memory m;
  interpreter it(m, {.skip_unmodelled = true});
  run(it, environment());
  run(it, {{ZBUF_1, 16 | 3 << 24}, {TEST_1, always}, {PRIM, SPRITE}, {XYZ2, xyz(0, 0)}, {XYZ2, xyz(16, 16)}});
  ASSERT_EQ(it.unmodelled_features().size(), 1u);
  EXPECT_EQ(it.unmodelled_features()[0].what.rfind("SPRITE: context 1 registers: ZBUF_1.PSM", 0), 0u)
      << it.unmodelled_features()[0].what;
}

TEST(Draw, XyoffsetAndScissorPlaceAndClipThePrimitive) {
  fixture f;
  // OFX = 100 px, OFY = 50 px: vertex (101, 52) .. (103, 53) lands on window (1, 2) .. (3, 3).
  run(f.it, {{XYOFFSET_1, std::uint64_t{100 * 16} | std::uint64_t{50 * 16} << 32},
             {PRIM, SPRITE},
             {RGBAQ, rgbaq(9, 9, 9, 9)},
             {XYZ2, xyz(101 * 16, 52 * 16)},
             {XYZ2, xyz(103 * 16, 53 * 16)}});
  EXPECT_EQ(f.px(1, 2), 0x09090909u);
  EXPECT_EQ(f.px(2, 2), 0x09090909u);
  EXPECT_EQ(f.count_nonzero(), 2);
  // SCISSOR 2..3 × 0..63 clips a 0..8 sprite to columns 2 and 3.
  fixture g;
  run(g.it, {{SCISSOR_1, scissor(2, 3, 0, 63)},
             {PRIM, SPRITE},
             {RGBAQ, rgbaq(5, 5, 5, 5)},
             {XYZ2, xyz(0, 0)},
             {XYZ2, xyz(8 * 16, 16)}});
  EXPECT_EQ(g.px(2, 0), 0x05050505u);
  EXPECT_EQ(g.px(3, 0), 0x05050505u);
  EXPECT_EQ(g.count_nonzero(), 2);
}

TEST(Draw, ContextTwoUsesItsOwnFrameOffsetAndScissorAlsoThroughPrmode) {
  fixture f;
  const mem::buffer fb8{fixed::uint<14>::from_wrapped(8 * 32), fixed::uint<6>::from_wrapped(1), mem::psm::PSMCT32};
  run(f.it, {{FRAME_2, frame(8, 1)},
             {SCISSOR_2, scissor(0, 63, 0, 63)},
             {XYOFFSET_2, 16},  // OFX 1 px
             {PRIM, SPRITE | CTXT},
             {RGBAQ, rgbaq(7, 7, 7, 7)},
             {XYZ2, xyz(16, 0)},
             {XYZ2, xyz(48, 16)}});
  EXPECT_EQ(f.count_nonzero(), 0);  // context 1's frame untouched
  EXPECT_EQ(f.px(0, 0, fb8), 0x07070707u);
  EXPECT_EQ(f.px(1, 0, fb8), 0x07070707u);
  EXPECT_EQ(f.count_nonzero(fb8), 2);
  // PRMODECONT.AC = 0: CTXT comes from PRMODE, PRIM's own CTXT bit is ignored.
  run(f.it, {{PRMODECONT, 0},
             {PRMODE, CTXT},
             {PRIM, SPRITE},
             {RGBAQ, rgbaq(3, 3, 3, 3)},
             {XYZ2, xyz(16, 32)},
             {XYZ2, xyz(32, 48)}});
  EXPECT_EQ(f.px(0, 2, fb8), 0x03030303u);
  EXPECT_EQ(f.count_nonzero(), 0);
}

TEST(Draw, DepthTestGequalGreaterAndZmsk) {
  fixture f;
  const mem::buffer zb{fixed::uint<14>::from_wrapped(16 * 32), fixed::uint<6>::from_wrapped(1), mem::psm::PSMZ32};
  const std::uint64_t gequal = 1 << 16 | 2 << 17, greater = 1 << 16 | 3 << 17;
  run(f.it, {{ZBUF_1, 16},
             {TEST_1, gequal},
             {PRIM, SPRITE},
             {RGBAQ, rgbaq(255, 0, 0, 1)},
             {XYZ2, xyz(0, 0, 100)},
             {XYZ2, xyz(64, 64, 100)},  // A: 0..3, Z 100
             {RGBAQ, rgbaq(0, 255, 0, 1)},
             {XYZ2, xyz(32, 32, 50)},
             {XYZ2, xyz(96, 96, 50)},  // B: 2..5, Z 50
             {RGBAQ, rgbaq(0, 0, 255, 1)},
             {XYZ2, xyz(48, 48, 200)},
             {XYZ2, xyz(80, 80, 200)}});  // C: 3..4, Z 200
  EXPECT_EQ(f.px(1, 1), 0x010000FFu);
  EXPECT_EQ(f.px(2, 2), 0x010000FFu);  // B's 50 < A's 100 fails GEQUAL
  EXPECT_EQ(f.px(5, 5), 0x0100FF00u);
  EXPECT_EQ(f.px(5, 2), 0x0100FF00u);
  EXPECT_EQ(f.px(3, 3), 0x01FF0000u);
  EXPECT_EQ(f.px(4, 4), 0x01FF0000u);
  EXPECT_EQ(f.px(1, 1, zb), 100u);
  EXPECT_EQ(f.px(5, 5, zb), 50u);
  EXPECT_EQ(f.px(3, 3, zb), 200u);
  // GREATER with an equal Z fails; GEQUAL passes; ZMSK = 1 leaves Z as it was.
  run(f.it, {{TEST_1, greater}, {RGBAQ, rgbaq(1, 1, 1, 1)}, {XYZ2, xyz(16, 16, 100)}, {XYZ2, xyz(32, 32, 100)}});
  EXPECT_EQ(f.px(1, 1), 0x010000FFu);
  run(f.it, {{TEST_1, gequal},
             {ZBUF_1, 16 | std::uint64_t{1} << 32},
             {RGBAQ, rgbaq(2, 2, 2, 2)},
             {XYZ2, xyz(16, 16, 300)},
             {XYZ2, xyz(32, 32, 300)}});
  EXPECT_EQ(f.px(1, 1), 0x02020202u);
  EXPECT_EQ(f.px(1, 1, zb), 100u);
}

// The interpreter's Gouraud triangle against gs::gouraud_triangle read by gs::gouraud_colour under `setup`.
void expect_gouraud_triangle_plane_on_the_fill_rules_pixels(gs::gouraud_setup setup) {
  interpreter_options o;
  o.model.setup = setup;
  fixture f(o);
  // Window vertices (2.25, 1.5), (20.75, 6), (5.5, 17.25) with XYOFFSET 2048 px, as the renderer sets it.
  const std::array<std::array<std::int32_t, 2>, 3> w{{{36, 24}, {332, 96}, {88, 276}}};
  const std::array<gs::rgba8, 3> c{gs::rgba8::from_u32(0xFF0000FFu), gs::rgba8::from_u32(0x8000FF00u),
                                   gs::rgba8::from_u32(0x00FF0000u)};
  writes ws{{XYOFFSET_1, std::uint64_t{2048 * 16} | std::uint64_t{2048 * 16} << 32}, {PRIM, TRIANGLE | IIP}};
  for (std::size_t k = 0; k < 3; ++k) {
    ws.push_back({RGBAQ, rgbaq(c[k].r.value(), c[k].g.value(), c[k].b.value(), c[k].a.value())});
    ws.push_back(
        {XYZ2, xyz(static_cast<std::uint64_t>(w[k][0] + 2048 * 16), static_cast<std::uint64_t>(w[k][1] + 2048 * 16))});
  }
  run(f.it, ws);
  // Reference pixel: the top-left pixel, (ceil 2.25, ceil 1.5) = (3, 2), in the 2048-offset space.
  const auto plane =
      gs::gouraud_triangle({w[0][0] + 32768, w[0][1] + 32768, c[0]}, {w[1][0] + 32768, w[1][1] + 32768, c[1]},
                           {w[2][0] + 32768, w[2][1] + 32768, c[2]}, 3 + 2048, 2 + 2048);
  ASSERT_TRUE(plane);
  const gs::triangle_setup t = gs::setup_triangle({gs::xy124{36, 24}, gs::xy124{332, 96}, gs::xy124{88, 276}});
  int covered = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      std::uint32_t want = 0;
      if (gs::covers(t, x, y)) {
        const gs::fragment_colour cf = gs::gouraud_colour(*plane, x + 2048, y + 2048, setup);
        want = gs::rgba8{gs::integer_part(cf.r), gs::integer_part(cf.g), gs::integer_part(cf.b), gs::integer_part(cf.a)}
                   .to_u32();
        ++covered;
      }
      ASSERT_EQ(f.px(x, y), want) << x << "," << y;
    }
  EXPECT_GT(covered, 100);
  EXPECT_EQ(f.it.pixels_drawn(), static_cast<std::uint64_t>(covered));
}

TEST(Draw, GouraudTriangleIsGouraudTrianglePlaneOnTheFillRulesPixels) {
  expect_gouraud_triangle_plane_on_the_fill_rules_pixels(gs::gouraud_setup::plane_steps);
}
TEST(Draw, PerPixelGouraudTriangleIsTheExactPlaneOnTheFillRulesPixels) {
  expect_gouraud_triangle_plane_on_the_fill_rules_pixels(gs::gouraud_setup::per_pixel);
}

TEST(Draw, FlooredGouraudTriangleIsTheExactPlaneFlooredOnTheFillRulesPixels) {
  expect_gouraud_triangle_plane_on_the_fill_rules_pixels(gs::gouraud_setup::per_pixel_floor);
}

TEST(Draw, FlatRightTriangleCoversTheTopLeftRulesTenPixels) {
  fixture f;
  // (0, 0), (4, 0), (0, 4): x, y >= 0 and x + y < 4 (the hypotenuse is a right edge): 4 + 3 + 2 + 1 pixels.
  run(f.it, {{PRIM, TRIANGLE}, {RGBAQ, rgbaq(1, 2, 3, 4)}, {XYZ2, xyz(0, 0)}, {XYZ2, xyz(64, 0)}, {XYZ2, xyz(0, 64)}});
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_EQ(f.px(x, y), x + y < 4 ? 0x04030201u : 0u) << x << "," << y;
}

TEST(Draw, VertexQueueStripFanListAndXyz3) {
  const writes square_strip{{PRIM, STRIP},       {RGBAQ, rgbaq(1, 1, 1, 1)}, {XYZ2, xyz(0, 0)},
                            {XYZ2, xyz(128, 0)}, {XYZ2, xyz(0, 128)},        {XYZ2, xyz(128, 128)}};
  const writes square_fan{{PRIM, FAN},         {RGBAQ, rgbaq(1, 1, 1, 1)}, {XYZ2, xyz(0, 0)},
                          {XYZ2, xyz(128, 0)}, {XYZ2, xyz(128, 128)},      {XYZ2, xyz(0, 128)}};
  for (const writes& w : {square_strip, square_fan}) {
    fixture f;
    run(f.it, w);
    // Two triangles tiling the 8×8 square: each of its 64 pixels drawn exactly once.
    EXPECT_EQ(f.it.primitives_drawn(), 2u);
    EXPECT_EQ(f.it.pixels_drawn(), 64u);
    EXPECT_EQ(f.count_nonzero(), 64);
  }
  fixture list;  // TRIANGLE: the fourth vertex starts the next triangle; x + y < 8 is 8 + 7 + ... + 1 = 36
  run(list.it, {{PRIM, TRIANGLE},
                {RGBAQ, rgbaq(1, 1, 1, 1)},
                {XYZ2, xyz(0, 0)},
                {XYZ2, xyz(128, 0)},
                {XYZ2, xyz(0, 128)},
                {XYZ2, xyz(128, 128)}});
  EXPECT_EQ(list.it.primitives_drawn(), 1u);
  EXPECT_EQ(list.count_nonzero(), 36);
  fixture xyz3;  // the third vertex through XYZ3: only the strip's second triangle, x + y >= 8: 64 − 36
  run(xyz3.it, {{PRIM, STRIP},
                {RGBAQ, rgbaq(1, 1, 1, 1)},
                {XYZ2, xyz(0, 0)},
                {XYZ2, xyz(128, 0)},
                {XYZ3, xyz(0, 128)},
                {XYZ2, xyz(128, 128)}});
  EXPECT_EQ(xyz3.it.primitives_drawn(), 1u);
  EXPECT_EQ(xyz3.count_nonzero(), 28);
  EXPECT_EQ(xyz3.px(7, 1), 0x01010101u);
  EXPECT_EQ(xyz3.px(6, 1), 0u);
}

TEST(Draw, TexturedSpriteReadsPsmt8ThroughTheClutLoadedOnTex0) {
  fixture f;
  packet_builder pb;
  // The 16×16 PSMT8 texture (index y·16 + x) at block 2048, TBW 2; the CLUT image, PSMCT32 16×16, at
  // block 4096, CLUT raster position p holding clut_word(p).
  const writes tex_upload{{0x50, std::uint64_t{2048} << 32 | std::uint64_t{2} << 48 | std::uint64_t{0x13} << 56},
                          {0x51, 0},
                          {0x52, 16 | std::uint64_t{16} << 32},
                          {0x53, 0}};
  pb.ad(tex_upload);
  std::vector<std::uint8_t> idx(256);
  for (unsigned i = 0; i < 256; ++i) idx[i] = static_cast<std::uint8_t>(i);
  pb.image(idx);
  const writes clut_upload{{0x50, std::uint64_t{4096} << 32 | std::uint64_t{1} << 48},
                           {0x51, 0},
                           {0x52, 16 | std::uint64_t{16} << 32},
                           {0x53, 0}};
  pb.ad(clut_upload);
  std::vector<std::uint8_t> words;
  for (unsigned p = 0; p < 256; ++p)
    for (int b = 0; b < 4; ++b) words.push_back(static_cast<std::uint8_t>(clut_word(p) >> (8 * b)));
  pb.image(words);
  // TEX0: TBP0 2048, TBW 2 (bit 14), PSMT8 (bit 20), TW = TH = 4, TCC = RGBA (bit 34), TFX = DECAL
  // (bit 35), CBP 4096 (bit 37), CPSM PSMCT32, CSM1, CLD = 1 (bit 61).
  const std::uint64_t tex0 = 2048 | 2 << 14 | std::uint64_t{0x13} << 20 | std::uint64_t{4} << 26 |
                             std::uint64_t{4} << 30 | std::uint64_t{1} << 34 | std::uint64_t{1} << 35 |
                             std::uint64_t{4096} << 37 | std::uint64_t{1} << 61;
  // UV (0.5, 0.5) .. (16.5, 16.5) over pixels 0..15: pixel x samples texel x (nearest, TEX1 = 0).
  const writes draw{
      {TEX0_1, tex0},    {TEX1_1, 0},       {PRIM, SPRITE | TME | FST}, {RGBAQ, rgbaq(128, 128, 128, 128)},
      {UV, 8 | 8 << 16}, {XYZ2, xyz(0, 0)}, {UV, 264 | 264 << 16},      {XYZ2, xyz(256, 256)}};
  pb.ad(draw, true);
  const auto bytes = pb.bytes();
  for (const gif_event& e : decode_gif(bytes)) f.it.apply(e, 16u * e.offset);
  ASSERT_TRUE(f.it.unmodelled_features().empty());
  for (unsigned y = 0; y < 16; ++y)
    for (unsigned x = 0; x < 16; ++x)
      ASSERT_EQ(f.px(static_cast<int>(x), static_cast<int>(y)), clut_word(csm1_raster(y * 16 + x))) << x << "," << y;
  EXPECT_EQ(f.count_nonzero(), 256);
}

// Perspective texturing (FST = 0, Q = 1/w differing per vertex) against the projective map written
// another way: at a pixel the texel is floor(64 · Σλ_i·S_i / Σλ_i·Q_i), the barycentrics λ_i in double
// from the pixel's position. The 64×64 PSMCT32 texture holds (u, v) in each texel, read with DECAL and
// nearest; pixels within 1/1000 of a texel of a boundary are left to the float rounding the model
// chooses (perspective.hpp) and counted.
TEST(Draw, PerspectiveTriangleReadsTheTexelOfTheProjectiveMap) {
  fixture f;
  packet_builder pb;
  const writes upload{{0x50, std::uint64_t{2048} << 32 | std::uint64_t{1} << 48},  // BITBLTBUF: DBP 2048, DBW 1
                      {0x51, 0},
                      {0x52, 64 | std::uint64_t{64} << 32},
                      {0x53, 0}};
  pb.ad(upload);
  std::vector<std::uint8_t> words;
  for (unsigned v = 0; v < 64; ++v)
    for (unsigned u = 0; u < 64; ++u)
      for (const unsigned b : {u, v, 0u, 0x80u}) words.push_back(static_cast<std::uint8_t>(b));
  pb.image(words);
  // TEX0: TBP0 2048, TBW 1, PSMCT32, TW = TH = 6, TCC = RGBA, TFX = DECAL; TEX1 = LCM 1, K 0: magnified,
  // nearest; CLAMP_1 = 0: REPEAT.
  const std::uint64_t tex0 = 2048 | 1 << 14 | std::uint64_t{6} << 26 | std::uint64_t{6} << 30 | std::uint64_t{1} << 34 |
                             std::uint64_t{1} << 35;
  struct corner {
    double x, y, w, s, t;
  };
  const corner c[3] = {{2.0, 2.0, 1.0, 0.05, 0.10}, {61.0, 6.5, 2.5, 0.95, 0.20}, {9.25, 60.0, 4.0, 0.30, 0.90}};
  auto bits = [](double v) { return std::bit_cast<std::uint32_t>(static_cast<float>(v)); };
  writes draw{{TEX0_1, tex0}, {TEX1_1, 1}, {PRIM, TRIANGLE | TME}};
  for (const corner& k : c) {
    draw.push_back({RGBAQ, 0x80808080 | std::uint64_t{bits(1.0 / k.w)} << 32});
    draw.push_back({0x02, bits(k.s / k.w) | std::uint64_t{bits(k.t / k.w)} << 32});  // ST
    draw.push_back({XYZ2, xyz(static_cast<std::uint64_t>(k.x * 16), static_cast<std::uint64_t>(k.y * 16))});
  }
  pb.ad(draw, true);
  const auto bytes = pb.bytes();
  for (const gif_event& e : decode_gif(bytes)) f.it.apply(e, 16u * e.offset);
  ASSERT_TRUE(f.it.unmodelled_features().empty());
  const double area = (c[1].x - c[0].x) * (c[2].y - c[0].y) - (c[1].y - c[0].y) * (c[2].x - c[0].x);
  int checked = 0, near_boundary = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const std::uint32_t got = f.px(x, y);
      double l[3];
      for (int i = 0; i < 3; ++i) {
        const corner &a = c[(i + 1) % 3], &b = c[(i + 2) % 3];
        l[i] = ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x)) / area;
      }
      if (got == 0) continue;  // not covered (the fill rule is tested above)
      double S = 0, T = 0, Q = 0;
      for (int i = 0; i < 3; ++i) S += l[i] * c[i].s / c[i].w, T += l[i] * c[i].t / c[i].w, Q += l[i] / c[i].w;
      const double u = 64.0 * S / Q, v = 64.0 * T / Q;
      if (std::fabs(u - std::round(u)) < 1e-3 || std::fabs(v - std::round(v)) < 1e-3) {
        ++near_boundary;
        continue;
      }
      const auto eu = static_cast<std::uint32_t>(std::floor(u)), ev = static_cast<std::uint32_t>(std::floor(v));
      ASSERT_EQ(got, 0x80000000u | ev << 8 | eu) << x << "," << y << " u " << u << " v " << v;
      ++checked;
    }
  EXPECT_GT(checked, 1300);  // of the triangle's ~1 400 pixels
  EXPECT_LT(near_boundary, checked / 100);
}

TEST(Draw, Psmt8ThroughASixteenBitClutIsWidenedWithTexa) {
  fixture f;
  packet_builder pb;
  // The 16×16 PSMT8 texture (index y·16 + x) at block 2048, TBW 2; a PSMCT16 CLUT image 16×16 at block
  // 4096 whose raster position p holds (p & 31) | 0x8000 for odd p (red p & 31, A bit set), p << 5 for
  // even p (green, A bit clear). TEXA TA0 0x11, TA1 0x99, AEM 0.
  pb.ad(writes{{0x50, std::uint64_t{2048} << 32 | std::uint64_t{2} << 48 | std::uint64_t{0x13} << 56},
               {0x51, 0},
               {0x52, 16 | std::uint64_t{16} << 32},
               {0x53, 0}});
  std::vector<std::uint8_t> idx(256);
  for (unsigned i = 0; i < 256; ++i) idx[i] = static_cast<std::uint8_t>(i);
  pb.image(idx);
  pb.ad(writes{{0x50, std::uint64_t{4096} << 32 | std::uint64_t{1} << 48 | std::uint64_t{2} << 56},
               {0x51, 0},
               {0x52, 16 | std::uint64_t{16} << 32},
               {0x53, 0}});
  auto half = [](unsigned p) { return p % 2 == 1 ? (p & 31u) | 0x8000u : (p & 31u) << 5; };
  std::vector<std::uint8_t> halves;
  for (unsigned p = 0; p < 256; ++p)
    halves.push_back(static_cast<std::uint8_t>(half(p))), halves.push_back(static_cast<std::uint8_t>(half(p) >> 8));
  pb.image(halves);
  // TEX0 as the PSMCT32-CLUT test but CPSM = PSMCT16 (2, bit 51).
  const std::uint64_t tex0 = 2048 | 2 << 14 | std::uint64_t{0x13} << 20 | std::uint64_t{4} << 26 |
                             std::uint64_t{4} << 30 | std::uint64_t{1} << 34 | std::uint64_t{1} << 35 |
                             std::uint64_t{4096} << 37 | std::uint64_t{2} << 51 | std::uint64_t{1} << 61;
  pb.ad(writes{{0x3B, 0x11 | std::uint64_t{0x99} << 32},
               {TEX0_1, tex0},
               {PRIM, SPRITE | TME | FST},
               {UV, 8 | 8 << 16},
               {XYZ2, xyz(0, 0)},
               {UV, 264 | 264 << 16},
               {XYZ2, xyz(256, 256)}},
        true);
  const auto bytes = pb.bytes();
  for (const gif_event& e : decode_gif(bytes)) f.it.apply(e, 16u * e.offset);
  ASSERT_TRUE(f.it.unmodelled_features().empty()) << f.it.unmodelled_features()[0].what;
  for (unsigned y = 0; y < 16; ++y)
    for (unsigned x = 0; x < 16; ++x) {
      const unsigned p = csm1_raster(y * 16 + x);
      const std::uint32_t want = p % 2 == 1 ? 0x99000000u | ((p & 31u) << 3) : 0x11000000u | ((p & 31u) << 3) << 8;
      ASSERT_EQ(f.px(static_cast<int>(x), static_cast<int>(y)), want) << x << "," << y;
    }
}

TEST(Draw, SixteenBitTexelsTakeTheirAlphaFromTexa) {
  fixture f;
  packet_builder pb;
  // Three PSMCT16 texels at block 2048: 0x801F (red, A bit 1), 0x0000 (black, A bit 0), 0x03E0 (green).
  const writes upload{{0x50, std::uint64_t{2048} << 32 | std::uint64_t{1} << 48 | std::uint64_t{2} << 56},
                      {0x51, 0},
                      {0x52, 3 | std::uint64_t{1} << 32},
                      {0x53, 0}};
  pb.ad(upload);
  const std::vector<std::uint8_t> texels{0x1F, 0x80, 0x00, 0x00, 0xE0, 0x03};
  pb.image(texels);
  // TEXA TA0 0x40, AEM 1 (bit 15), TA1 0x90 (bit 32); TEX0 PSMCT16, TW 2, TH 0, TCC RGBA, DECAL.
  const std::uint64_t tex0 = 2048 | 1 << 14 | std::uint64_t{2} << 20 | std::uint64_t{2} << 26 | std::uint64_t{1} << 34 |
                             std::uint64_t{1} << 35;
  const writes draw{{0x3B, 0x40 | 1 << 15 | std::uint64_t{0x90} << 32},
                    {TEX0_1, tex0},
                    {PRIM, SPRITE | TME | FST},
                    {UV, 8 | 8 << 16},
                    {XYZ2, xyz(0, 0)},
                    {UV, 56 | 24 << 16},
                    {XYZ2, xyz(48, 16)}};
  pb.ad(draw, true);
  const auto bytes = pb.bytes();
  for (const gif_event& e : decode_gif(bytes)) f.it.apply(e, 16u * e.offset);
  // 5-bit channels widened as c << 3: 31 -> 0xF8. A = TA1 with the A bit, 0 for black under AEM, else TA0.
  EXPECT_EQ(f.px(0, 0), 0x900000F8u);
  EXPECT_EQ(f.px(1, 0), 0x00000000u);
  EXPECT_EQ(f.px(2, 0), 0x4000F800u);
  EXPECT_EQ(f.it.pixels_drawn(), 3u);
}

TEST(Draw, AClutThatCouldNotBeLoadedStaysUnmodelledUntilALoadSucceeds) {
  // PSMT8 4×4 texture, CBP 4096; CLD = 6 (reserved: refused), then CLD = 0 (no load: still refused), then
  // CLD = 1 (a CSM1 PSMCT32 load: drawn).
  const std::uint64_t t8 = 2048 | 2 << 14 | std::uint64_t{0x13} << 20 | std::uint64_t{2} << 26 |
                           std::uint64_t{2} << 30 | std::uint64_t{4096} << 37;
  const writes sprite{{PRIM, SPRITE | TME | FST}, {UV, 0}, {XYZ2, xyz(0, 0)}, {UV, 64 | 64 << 16}, {XYZ2, xyz(64, 64)}};
  mem::local_memory m;
  interpreter it(m, {.skip_unmodelled = true});
  run(it, environment());
  for (const std::uint64_t cld : {6, 0, 1}) {
    writes w{{TEX0_1, t8 | cld << 61}};
    w.insert(w.end(), sprite.begin(), sprite.end());
    run(it, w);
  }
  ASSERT_EQ(it.unmodelled_features().size(), 2u);
  for (const auto& u : it.unmodelled_features()) EXPECT_EQ(u.what.rfind("SPRITE: context 1 CLUT: ", 0), 0u) << u.what;
  EXPECT_EQ(it.primitives_drawn(), 1u);
  EXPECT_EQ(it.pixels_drawn(), 16u);
}

TEST(Draw, UnmodelledFeaturesAreNamedAndSkipped) {
  struct named {
    writes w;
    const char* what;
  };
  const named cases[] = {
      {{{PRIM, SPRITE | FGE}, {XYZ2, xyz(0, 0)}, {XYZ2, xyz(32, 32)}}, "SPRITE: PRIM.FGE = 1 (fog)"},
      {{{PRIM, TRIANGLE | AA1}, {XYZ2, xyz(0, 0)}, {XYZ2, xyz(32, 0)}, {XYZ2, xyz(0, 32)}},
       "TRIANGLE: PRIM.AA1 = 1 (anti-aliasing)"},
      {{{PRIM, 1}, {XYZ2, xyz(0, 0)}, {XYZ2, xyz(32, 32)}},
       "LINE: PRIM.PRIM = LINE (points and lines are not modelled)"},
      // TEX1: MXL 1 (bit 2), MMIN NEAREST_MIPMAP_NEAREST (2, bit 6), LCM 1, K = +1.0 (16, bit 32): minified.
      {{{TEX0_1, std::uint64_t{4} << 26 | std::uint64_t{4} << 30},
        {TEX1_1, 1 | 1 << 2 | 2 << 6 | std::uint64_t{16} << 32},
        {PRIM, SPRITE | TME | FST},
        {XYZ2, xyz(0, 0)},
        {XYZ2, xyz(32, 32)}},
       "SPRITE: context 1 mip-mapping (TEX1.MMIN = 2, MXL = 1)"},
      // ST/Q texturing (FST = 0) with Q = 0.0 (RGBAQ bits 32-63) and S = T = 1.0: S/Q is not a number the
      // model can sample at (the fuzzer's regression-stq-nan); TEX1.LCM = 1 so the LOD needs no Q.
      {{{TEX0_1, std::uint64_t{4} << 26 | std::uint64_t{4} << 30},
        {TEX1_1, 1},
        {PRIM, SPRITE | TME},
        {RGBAQ, 0x80808080},
        {0x02, 0x3F800000 | std::uint64_t{0x3F800000} << 32},
        {XYZ2, xyz(0, 0)},
        {XYZ2, xyz(32, 32)}},
       "SPRITE: PRIM.FST = 0 with S/Q or T/Q not a finite number (Q = 0, or a NaN / infinite S, T or Q)"},
      // Q = 1 and Q = -1 on one triangle: Q is 0 between them, and the sources treat negative Q apart.
      {{{TEX0_1, std::uint64_t{4} << 26 | std::uint64_t{4} << 30},
        {TEX1_1, 1},
        {PRIM, TRIANGLE | TME},
        {RGBAQ, 0x80808080 | std::uint64_t{0x3F800000} << 32},
        {XYZ2, xyz(0, 0)},
        {XYZ2, xyz(32, 0)},
        {RGBAQ, 0x80808080 | std::uint64_t{0xBF800000} << 32},
        {XYZ2, xyz(0, 32)}},
       "TRIANGLE: PRIM.FST = 0 with Q of both signs"},
      // A sprite's two Q differ: which one the GS takes is not known (PCSX2 takes the second's).
      {{{TEX0_1, std::uint64_t{4} << 26 | std::uint64_t{4} << 30},
        {TEX1_1, 1},
        {PRIM, SPRITE | TME},
        {RGBAQ, 0x80808080 | std::uint64_t{0x3F800000} << 32},
        {XYZ2, xyz(0, 0)},
        {RGBAQ, 0x80808080 | std::uint64_t{0x40000000} << 32},
        {XYZ2, xyz(32, 32)}},
       "SPRITE: PRIM.FST = 0 on a SPRITE with differing Q"},
  };
  for (const named& c : cases) {
    mem::local_memory m;
    interpreter it(m, {.skip_unmodelled = true});
    run(it, environment());
    run(it, c.w);
    ASSERT_EQ(it.unmodelled_features().size(), 1u) << c.what;
    EXPECT_EQ(it.unmodelled_features()[0].what, c.what);
    EXPECT_EQ(it.primitives_skipped(), 1u);
    EXPECT_EQ(it.pixels_drawn(), 0u);
    interpreter strict(m);
    run(strict, environment());
    EXPECT_THROW(run(strict, c.w), unmodelled_error) << c.what;
  }
}

// A dump that displays an 8×4 PSMCT32 frame: PMODE.EN1 (bit 0 at 0x00), DISPFB1 (0x70) FBP 0, FBW 1
// (bit 9), DISPLAY1 (0x80) DW 7 (bit 32), DH 3 (bit 44); one sprite (1, 1) .. (5, 3) of colour
// (10, 20, 30, 40). make_pngs.py writes the frame's PNG from the same numbers for the CLI test.
gs::dump::gs_dump display_dump() {
  packet_builder pb;
  writes w = environment();
  const writes sprite{{PRIM, SPRITE}, {RGBAQ, rgbaq(10, 20, 30, 40)}, {XYZ2, xyz(16, 16)}, {XYZ2, xyz(80, 48)}};
  w.insert(w.end(), sprite.begin(), sprite.end());
  pb.ad(w, true);
  gs::dump::gs_dump d;
  d.state_version = 8;
  d.state = gs::dump::make_state_v8();
  std::vector<std::uint8_t> regs(gs::dump::privileged_bytes, 0);
  auto put = [&](std::size_t at, std::uint64_t v) {
    for (int b = 0; b < 8; ++b) regs[at + static_cast<std::size_t>(b)] = static_cast<std::uint8_t>(v >> (8 * b));
  };
  put(0x00, 1);
  put(0x70, std::uint64_t{1} << 9);
  put(0x80, std::uint64_t{7} << 32 | std::uint64_t{3} << 44);
  d.packets.push_back({gs::dump::packet_type::transfer, 2, 0, 0, pb.bytes(), 0});
  d.packets.push_back({gs::dump::packet_type::registers, 0, 0, 0, regs, 0});
  d.packets.push_back({gs::dump::packet_type::vsync, 0, 0, 0, {}, 0});
  return d;
}

TEST(Display, TheRegisterPacketSelectsReadCircuitOnesRectangle) {
  mem::local_memory m;
  interpreter it(m);
  it.replay(gs::dump::read_dump(gs::dump::write_dump(display_dump())));
  const display_state s = decode_display(it.privileged());
  ASSERT_TRUE(s.frame);
  EXPECT_TRUE(s.unmodelled.empty());
  EXPECT_EQ(s.frame->circuit, 1u);
  EXPECT_EQ(s.frame->width, 8u);
  EXPECT_EQ(s.frame->height, 4u);
  EXPECT_EQ(s.frame->buffer, fb0);
  EXPECT_EQ(m.read_pixel(fb0, 4, 2), 0x281E140Au);
  // Both circuits on: circuit 1 shown, the merge circuit named; neither: no frame.
  std::vector<std::uint8_t> regs = it.privileged();
  regs[0] = 3;
  EXPECT_EQ(decode_display(regs).unmodelled,
            "PMODE: both read circuits enabled; the merge circuit is not modelled (circuit 1 shown)");
  regs[0] = 0;
  EXPECT_FALSE(decode_display(regs).frame);
}

// Writes the display dump where the replay --expect CLI test reads it (GSDOT3_DISPLAY_DUMP), when asked.
TEST(Display, WritesTheDisplayDumpForTheCliTest) {
  const char* out = std::getenv("GSDOT3_DISPLAY_DUMP");
  if (out == nullptr) GTEST_SKIP() << "GSDOT3_DISPLAY_DUMP not set";
  gs::dump::save_dump(out, display_dump());
  EXPECT_EQ(gs::dump::write_dump(gs::dump::load_dump(out)), gs::dump::write_dump(display_dump()));
}

}  // namespace

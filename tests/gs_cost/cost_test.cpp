// The GS cost model against frames built by hand with gs_packets' builder: every expected figure is
// worked out here from the frame's geometry (pages of 64x32 PSMCT32 pixels, 8x2 / 4x2 blocks, the GIF's
// 8 bytes per cycle), written as its own formula, never read back from the model.
#include <gtest/gtest.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "gs_cost/model.hpp"
#include "gs_packets/builder.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/state.hpp"

namespace {

using namespace gs::packets;
namespace cost = gs::cost;
namespace dump = gs::dump;
using writes = std::vector<std::pair<std::uint8_t, std::uint64_t>>;

constexpr std::uint8_t PRIM = 0x00, UV = 0x03, XYZ2 = 0x05, TEX0_1 = 0x06, SCISSOR_1 = 0x40, ALPHA_1 = 0x42,
                       TEST_1 = 0x47, FRAME_1 = 0x4C, ZBUF_1 = 0x4E, PRMODECONT = 0x1A, XYOFFSET_1 = 0x18;

constexpr std::uint64_t frame(std::uint64_t fbp, std::uint64_t fbw, std::uint64_t psm = 0) {
  return fbp | fbw << 16 | psm << 24;
}
constexpr std::uint64_t scissor_all = 2047ull << 16 | 2047ull << 48;
constexpr std::uint64_t xyz(std::uint64_t x, std::uint64_t y) { return (x << 4) | (y << 4) << 16; }
constexpr std::uint64_t uv(std::uint64_t u, std::uint64_t v) { return (u << 4) | (v << 4) << 16; }
constexpr std::uint64_t tex0(std::uint64_t tbp0, std::uint64_t tbw, std::uint64_t psm, std::uint64_t tw,
                             std::uint64_t th) {
  return tbp0 | tbw << 14 | psm << 20 | tw << 26 | th << 30 | 1ull << 35;  // TFX = DECAL
}

writes environment(std::uint64_t frame_value) {
  return {{PRMODECONT, 1},        {XYOFFSET_1, 0}, {SCISSOR_1, scissor_all},
          {FRAME_1, frame_value}, {TEST_1, 0},     {ZBUF_1, 1ull << 32}};
}

dump::gs_dump dump_of(const packet_builder& pb, int frames = 1) {
  dump::gs_dump d;
  d.state_version = 8;
  d.state = dump::make_state_v8();
  d.packets.push_back({dump::packet_type::transfer, 2, 0, 0, pb.bytes(), 0});
  for (int i = 0; i < frames; ++i) d.packets.push_back({dump::packet_type::vsync, 0, 0, 0, {}, 0});
  return dump::read_dump(dump::write_dump(d));
}

void sprite(packet_builder& pb, std::uint64_t prim, unsigned x0, unsigned y0, unsigned x1, unsigned y1) {
  pb.ad(writes{{PRIM, prim}, {UV, uv(0, 0)}, {XYZ2, xyz(x0, y0)}, {UV, uv(x1 - x0, y1 - y0)}, {XYZ2, xyz(x1, y1)}});
}

const cost::cost_options defaults{};

// An untextured W x H sprite at the origin of a PSMCT32 frame FBW pages wide: W·H/16 pixel cycles; a page
// break at each page a band enters, (H/2)·(W/64) of them when W spans several pages.
TEST(Cost, UntexturedSpriteIsWidthTimesHeightOverSixteenPlusItsPageBreaks) {
  packet_builder pb;
  pb.ad(environment(frame(0, 2)));
  sprite(pb, 6, 0, 0, 128, 64);
  const auto frames = cost::price_dump(dump_of(pb));
  ASSERT_EQ(frames.size(), 1u);
  ASSERT_EQ(frames[0].passes.size(), 1u);
  const auto& p = frames[0].passes[0];
  EXPECT_EQ(p.counts.pixels, 128u * 64u);
  EXPECT_EQ(p.cycles.pixels, 128u * 64u / 16u);
  EXPECT_EQ(p.counts.page_breaks, (64u / 2u) * (128u / 64u));
  EXPECT_EQ(p.cycles.page_breaks, 64u * defaults.page_break_cycles);
  EXPECT_EQ(p.cycles.setup, defaults.sprite_setup_cycles);
  EXPECT_EQ(frames[0].cycles.total(), 1u + 512u + 64u * 10u);
}

// One page wide: the band stays in its page, which changes every 32 rows only.
TEST(Cost, APageWideSpriteBreaksEveryThirtyTwoRows) {
  packet_builder pb;
  pb.ad(environment(frame(0, 1)));
  sprite(pb, 6, 0, 0, 64, 128);
  const auto frames = cost::price_dump(dump_of(pb));
  EXPECT_EQ(frames.at(0).counts.page_breaks, 128u / 32u);
  EXPECT_EQ(frames[0].cycles.pixels, 64u * 128u / 16u);
}

// Textured (FST, one texel per pixel, a PSMCT32 texture laid out like the frame): 8 pixels per cycle,
// and the texture walk enters a texture page as often as the frame walk enters a frame page.
TEST(Cost, TexturedSpriteIsEightPixelsPerCycleAndMissesAtEveryTexturePage) {
  packet_builder pb;
  pb.ad(environment(frame(0, 2)));
  pb.ad(writes{{TEX0_1, tex0(64 * 32, 2, 0, 7, 6)}});
  sprite(pb, 6 | 1 << 4 | 1 << 8, 0, 0, 128, 64);  // SPRITE, TME, FST
  const auto frames = cost::price_dump(dump_of(pb));
  const auto& p = frames.at(0).passes.at(0);
  EXPECT_TRUE(p.mode.textured);
  EXPECT_EQ(p.cycles.pixels, 128u * 64u / 8u);
  EXPECT_EQ(p.counts.texture_misses, 2u * 32u);
  EXPECT_EQ(p.cycles.total(), 1u + 1024u + 64u * 10u + 64u * 10u);
}

// A known number of texture page crossings: one band of 64 pixels samples u = 0 .. 511 of a PSMT8
// texture (pages 128 texels wide), 8 texels per pixel: 512 / 128 = 4 pages, so 4 misses.
TEST(Cost, ATextureWalkMissesOncePerTexturePageItCrosses) {
  packet_builder pb;
  pb.ad(environment(frame(0, 1)));
  pb.ad(writes{{TEX0_1, tex0(64 * 32, 8, 0x13, 9, 1)}});
  pb.ad(writes{{PRIM, 6 | 1 << 4 | 1 << 8}, {UV, uv(0, 0)}, {XYZ2, xyz(0, 0)}, {UV, uv(512, 2)}, {XYZ2, xyz(64, 2)}});
  const auto frames = cost::price_dump(dump_of(pb));
  EXPECT_EQ(frames.at(0).counts.texture_misses, 512u / 128u);
  EXPECT_EQ(frames[0].counts.page_breaks, 1u);
  EXPECT_EQ(frames[0].counts.blocks, 64u / 4u);
}

// The triangle (0,0) (64,0) (0,64): row y covers x < 64 - y (the hypotenuse is a right edge), so
// 64·65/2 pixels; band b's hull is 64 - 2b wide, ceil((64 - 2b) / 8) blocks: four bands each of 1 .. 8
// blocks, 4·36; rows 0..31 and 32..63 are two pages; set-up 2 cycles.
TEST(Cost, TriangleCountsItsBlocksAndTwoCyclesOfSetUp) {
  packet_builder pb;
  pb.ad(environment(frame(0, 1)));
  pb.ad(writes{{PRIM, 3}, {XYZ2, xyz(0, 0)}, {XYZ2, xyz(64, 0)}, {XYZ2, xyz(0, 64)}});
  const auto frames = cost::price_dump(dump_of(pb));
  const auto& f = frames.at(0);
  EXPECT_EQ(f.counts.triangles, 1u);
  EXPECT_EQ(f.counts.pixels, 64u * 65u / 2u);
  EXPECT_EQ(f.counts.blocks, 4u * (1 + 2 + 3 + 4 + 5 + 6 + 7 + 8));
  EXPECT_EQ(f.counts.page_breaks, 2u);
  EXPECT_EQ(f.cycles.total(), 2u + 144u + 2u * 10u);
  cost::cost_options o;
  o.walk = cost::pixel_walk::pixels;  // the headline rate: ceil(2080 / 16) = 130
  EXPECT_EQ(cost::price_dump(dump_of(pb), o).at(0).cycles.pixels, 130u);
}

// A host -> local transfer of 32x16 PSMCT32 pixels: 2048 bytes over 8 bytes per cycle.
TEST(Cost, AnUploadCostsItsBytesOverTheGif) {
  packet_builder pb;
  pb.ad(writes{{0x50, 0x0001000000000000ull}, {0x51, 0}, {0x52, 0x0000001000000020ull}, {0x53, 0}});
  pb.image(std::vector<std::uint8_t>(32 * 16 * 4, 0x5A));
  const auto frames = cost::price_dump(dump_of(pb));
  ASSERT_EQ(frames.size(), 1u);
  ASSERT_EQ(frames[0].passes.size(), 1u);  // a transfers-only pass: no primitive follows
  EXPECT_EQ(frames[0].passes[0].counts.primitives, 0u);
  EXPECT_EQ(frames[0].counts.upload_bytes, 2048u);
  EXPECT_EQ(frames[0].cycles.uploads, 2048u / 8u);
  EXPECT_EQ(frames[0].cycles.total(), 256u);
}

// TEX0 with PSMT8 and CLD = 1 loads 256 CLUT entries: 1 KiB over the 64-byte texture bus (16 cycles)
// plus the option's 10; charged to the pass that follows.
TEST(Cost, AClutLoadIsChargedToTheNextPass) {
  packet_builder pb;
  pb.ad(environment(frame(0, 1)));
  pb.ad(writes{{TEX0_1, tex0(64 * 32, 1, 0x13, 6, 6) | 1ull << 61}});
  sprite(pb, 6, 0, 0, 8, 2);
  const auto frames = cost::price_dump(dump_of(pb));
  ASSERT_EQ(frames.at(0).passes.size(), 1u);
  EXPECT_EQ(frames[0].counts.clut_loads, 1u);
  EXPECT_EQ(frames[0].cycles.clut_loads, 256u * 4u / 64u + 10u);
  EXPECT_EQ(frames[0].cycles.total(), 26u + 1u + 1u + 10u);  // the 8x2 sprite: set-up, one block, one page
}

// Passes: a run of primitives with the same registers; a register change opens the next; a vsync
// closes the frame.
TEST(Cost, PassesSplitAtRegisterChangesAndFramesAtVsyncs) {
  packet_builder pb;
  pb.ad(environment(frame(0, 1)));
  sprite(pb, 6, 0, 0, 8, 2);
  sprite(pb, 6, 8, 0, 16, 2);
  pb.ad(writes{{ALPHA_1, 0x44}});
  sprite(pb, 6, 0, 2, 8, 4);
  const auto frames = cost::price_dump(dump_of(pb));
  ASSERT_EQ(frames.size(), 1u);
  ASSERT_EQ(frames[0].passes.size(), 2u);
  EXPECT_EQ(frames[0].passes[0].counts.primitives, 2u);
  EXPECT_EQ(frames[0].passes[1].counts.primitives, 1u);
  EXPECT_EQ(frames[0].counts.page_breaks, 1u);  // all in page 0
}

// Blending that reads the destination is full rate by default (constants.hpp); the what-if divisor 2
// doubles its pixel cycles and nothing else.
TEST(Cost, BlendRateDivisorScalesOnlyBlendedPixelCycles) {
  packet_builder pb;
  pb.ad(environment(frame(0, 1)));
  pb.ad(writes{{ALPHA_1, 0x44}});  // (Cs - Cd)·As + Cd
  sprite(pb, 6 | 1 << 6, 0, 0, 64, 32);
  cost::cost_options half;
  half.blend_rate_divisor = 2;
  const auto full = cost::price_dump(dump_of(pb)).at(0).cycles;
  const auto slow = cost::price_dump(dump_of(pb), half).at(0).cycles;
  EXPECT_EQ(full.pixels, 64u * 32u / 16u);
  EXPECT_EQ(slow.pixels, 2u * 64u * 32u / 16u);
  EXPECT_EQ(slow.total() - full.total(), 128u);
}

TEST(Cost, FramesPerSecondLockToWholeFields) {
  EXPECT_DOUBLE_EQ(cost::fps_locked(1, cost::ntsc_hz), 59.94);
  const auto field = static_cast<std::uint64_t>(cost::gs_clock_hz / 50.0);  // 2 949 120 cycles
  EXPECT_DOUBLE_EQ(cost::fps_locked(field, cost::pal_hz), 50.0);
  EXPECT_DOUBLE_EQ(cost::fps_locked(field + 1, cost::pal_hz), 25.0);
  EXPECT_NEAR(cost::seconds(147'456), 1e-3, 1e-15);
}

}  // namespace

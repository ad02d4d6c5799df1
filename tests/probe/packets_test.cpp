// The probe dump: it reads back, its texture upload lands where the model's frame takes it from (the
// packet interpreter), every vertex kick sees exactly the registers and vertices of the design's draw
// (decoded from the stream, compared field by field through gs_arith's decoders), and the display
// registers say 640x448 PSMCT32 at FBP 0.
#include <gtest/gtest.h>

#include <map>

#include "gs_memory/address.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/gs_registers.hpp"
#include "gs_packets/interpreter.hpp"
#include "probe/design.hpp"
#include "probe/packets.hpp"

namespace {

using namespace gsdot3::probe;
namespace dump = gs::dump;

std::uint64_t u64_at(const std::vector<std::uint8_t>& b, std::size_t at) {
  std::uint64_t v = 0;
  for (int k = 0; k < 8; ++k) v |= std::uint64_t{b[at + static_cast<std::size_t>(k)]} << (8 * k);
  return v;
}

TEST(ProbeDump, ReadsBackAndUploadsTheTexture) {
  const dump::gs_dump d = dump::read_dump(dump::write_dump(probe_dump()));
  EXPECT_EQ(d.state_version, 8u);
  gs::mem::local_memory m;
  gs::packets::interpreter it(m);
  it.load_state(d.state, d.state_version);
  it.replay(d);
  ASSERT_EQ(it.transfers().size(), 1u);
  const gs::mem::buffer tex{fixed::uint<14>::from_wrapped(texture_page * 32), fixed::uint<6>::from_wrapped(1),
                            gs::mem::psm::PSMCT32};
  const auto& texels = probe_design().texture;
  for (int v = 0; v < texture_side; ++v)
    for (int u = 0; u < texture_side; ++u)
      ASSERT_EQ(m.read_pixel(tex, static_cast<std::uint32_t>(u), static_cast<std::uint32_t>(v)),
                texels[static_cast<std::size_t>(v * texture_side + u)]);
  // Display (DobieStation's decoding, packets.hpp): DISPFB1 FBW 10 -> 640, PSM 0, FBP 0; DISPLAY1 DW + 1 =
  // 2560 VCK at MAGH + 1 = 4 -> 640 pixels, DH + 1 = 448; PMODE EN1, MMOD, ALP 0xff.
  const std::uint64_t pmode = u64_at(d.privileged, 0x0000), dispfb = u64_at(d.privileged, 0x0070),
                      display = u64_at(d.privileged, 0x0080);
  EXPECT_EQ(pmode & 1, 1u);
  EXPECT_EQ(pmode >> 8 & 0xFF, 0xFFu);
  EXPECT_EQ((dispfb >> 9 & 0x3F) * 64, 640u);
  EXPECT_EQ(dispfb & 0x1FF, 0u);
  EXPECT_EQ(dispfb >> 15 & 0x1F, 0u);
  EXPECT_EQ(((display >> 32 & 0xFFF) + 1) / ((display >> 23 & 0xF) + 1), 640u);
  EXPECT_EQ((display >> 44 & 0x7FF) + 1, 448u);
}

TEST(ProbeDump, EveryVertexKickSeesItsDrawsRegisters) {
  const dump::gs_dump d = probe_dump();
  const auto paths = dump::decode_paths(d);
  std::map<std::uint8_t, std::uint64_t> regs;
  std::size_t draw_index = 0, vertices = 0;
  bool texflush = false;
  std::vector<std::uint64_t> xyz;
  const auto& draws = probe_design().draws;
  for (const auto& e : paths[2].events) {
    if (e.what != gs::packets::gif_event::kind::reg_write) continue;
    if (e.address == 0x3F) texflush = true;
    regs[e.address] = e.value;
    if (e.address == gs::packets::reg::PRIM) vertices = 0;
    if (e.address != gs::packets::reg::XYZ2) continue;
    ASSERT_LT(draw_index, draws.size());
    const draw& dr = draws[draw_index];
    const vertex& v = dr.v[vertices];
    EXPECT_EQ(regs[0x01] & 0xFFFFFFFFu, v.rgba) << draw_index;
    EXPECT_EQ(regs[0x03], static_cast<std::uint64_t>(v.u16) | static_cast<std::uint64_t>(v.v16) << 16) << draw_index;
    EXPECT_EQ(e.value, static_cast<std::uint64_t>(v.x * 16) | static_cast<std::uint64_t>(v.y * 16) << 16) << draw_index;
    if (++vertices < dr.v.size()) continue;
    // The kick: every pixel-pipeline register decodes to the draw's value.
    EXPECT_EQ(gs::decode_prim(regs[0x00]), dr.regs.PRIM) << draw_index;
    EXPECT_EQ(gs::decode_tex0(regs[0x06]), dr.regs.TEX0_1) << draw_index;
    EXPECT_EQ(gs::decode_alpha(regs[0x42]), dr.regs.ALPHA_1) << draw_index;
    EXPECT_EQ(gs::decode_test(regs[0x47]), dr.regs.TEST_1) << draw_index;
    EXPECT_EQ(gs::decode_frame(regs[0x4C]), dr.regs.FRAME_1) << draw_index;
    EXPECT_EQ(gs::decode_colclamp(regs[0x46]), dr.regs.COLCLAMP) << draw_index;
    EXPECT_EQ(gs::decode_dthe(regs[0x45]), dr.regs.DTHE) << draw_index;
    EXPECT_EQ(gs::decode_dimx(regs[0x44]), dr.regs.DIMX) << draw_index;
    EXPECT_EQ(regs[0x14] >> 5 & 1, dr.linear ? 1u : 0u) << draw_index;  // TEX1_1 MMAG
    EXPECT_EQ(regs[0x40] & 0x7FF, static_cast<std::uint64_t>(dr.scissor.x0)) << draw_index;
    EXPECT_EQ(regs[0x40] >> 48 & 0x7FF, static_cast<std::uint64_t>(dr.scissor.y1)) << draw_index;
    EXPECT_EQ(texflush, dr.texflush) << draw_index;
    EXPECT_EQ(regs[0x4E] >> 32 & 1, 1u);  // ZBUF_1 ZMSK: no Z writes
    texflush = false;
    vertices = 0;
    ++draw_index;
  }
  EXPECT_EQ(draw_index, draws.size());
}

}  // namespace

// The packet interpreter: an IMAGE transfer in a dump lands in the modelled memory where the GS
// manual's transfer rule puts it (pixel words built by hand); a primitive the model cannot draw (a fog
// sprite) stops the replay with its dump byte offset (worked out from the layout in dump.hpp), or is
// skipped and listed with skip_unmodelled.
#include <gtest/gtest.h>

#include <cstdlib>

#include "gs_packets/builder.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/interpreter.hpp"
#include "gs_packets/state.hpp"

namespace {

using namespace gs::packets;
namespace dump = gs::dump;

// BITBLTBUF DBP 0 (bit 32), DBW 1 (bit 48), DPSM PSMCT32 (0, bit 56); TRXPOS DSAX 2 (bit 32), DSAY 1
// (bit 48); TRXREG RRW 4 (bit 0), RRH 2 (bit 32); TRXDIR 0; then 8 PSMCT32 pixels 0x11223340 + i.
dump::gs_dump upload_dump() {
  packet_builder pb;
  const std::pair<std::uint8_t, std::uint64_t> regs[] = {
      {0x50, 0x0001000000000000ull}, {0x51, 0x0001000200000000ull}, {0x52, 0x0000000200000004ull}, {0x53, 0}};
  pb.ad(regs);
  std::vector<std::uint8_t> img;
  for (std::uint32_t i = 0; i < 8; ++i)
    for (int b = 0; b < 4; ++b) img.push_back(static_cast<std::uint8_t>((0x11223340u + i) >> (8 * b)));
  pb.image(img);
  // PRIM = SPRITE (6) with FGE (bit 5), two XYZ2 corners: the second kicks a fog sprite.
  const std::pair<std::uint8_t, std::uint64_t> draw[] = {
      {0x00, 6 | 1 << 5}, {0x05, 0x0000000001000100ull}, {0x05, 0x0000000002000200ull}};
  pb.ad(draw, true);
  dump::gs_dump d;
  d.state_version = 8;
  d.state = dump::make_state_v8();
  d.packets.push_back({dump::packet_type::transfer, 2, 0, 0, pb.bytes(), 0});
  d.packets.push_back({dump::packet_type::vsync, 0, 0, 0, {}, 0});
  dump::assign_offsets(d);
  return d;
}

TEST(Interpreter, ImageTransferReachesMemoryAndAnUnmodelledPrimitiveIsSkipped) {
  const dump::gs_dump d = dump::read_dump(dump::write_dump(upload_dump()));
  gs::mem::local_memory m;
  interpreter it(m, {.skip_unmodelled = true});
  it.replay(d);
  const gs::mem::buffer fb{fixed::uint<14>::from_wrapped(0), fixed::uint<6>::from_wrapped(1), gs::mem::psm::PSMCT32};
  for (std::uint32_t y = 0; y < 2; ++y)
    for (std::uint32_t x = 0; x < 4; ++x) EXPECT_EQ(m.read_pixel(fb, 2 + x, 1 + y), 0x11223340u + 4 * y + x);
  EXPECT_EQ(m.read_pixel(fb, 1, 1), 0u);
  EXPECT_EQ(m.read_pixel(fb, 6, 1), 0u);
  ASSERT_EQ(it.transfers().size(), 1u);
  // Transfer data at 8 + 36 + 4194752 + 8192 + 6 = 4202994; the second XYZ2 write is qword 11.
  ASSERT_EQ(it.unmodelled_features().size(), 1u);
  EXPECT_EQ(it.unmodelled_features()[0].what, "SPRITE: PRIM.FGE = 1 (fog)");
  EXPECT_EQ(it.unmodelled_features()[0].offset, 4202994u + 16 * 11);
  EXPECT_EQ(it.primitives_skipped(), 1u);
  EXPECT_EQ(it.primitives_drawn(), 0u);
  EXPECT_EQ(it.reg(0x52), 0x0000000200000004ull);
}

TEST(Interpreter, AnUnmodelledPrimitiveStopsTheReplay) {
  const dump::gs_dump d = dump::read_dump(dump::write_dump(upload_dump()));
  gs::mem::local_memory m;
  interpreter it(m);
  try {
    it.replay(d);
    FAIL() << "no unmodelled_error";
  } catch (const unmodelled_error& e) {
    EXPECT_STREQ(e.what(), ("byte " + std::to_string(4202994u + 16 * 11) + ": SPRITE: PRIM.FGE = 1 (fog)").c_str());
  }
}

TEST(Interpreter, IncompleteAndLocalToHostTransfersAreReported) {
  dump::gs_dump d = upload_dump();
  d.packets[0].data.resize(16 * 7);  // the IMAGE's second qword is cut: tag NLOOP 2 with one qword
  EXPECT_THROW(dump::decode_paths(d), dump::dump_error);
  packet_builder pb;
  const std::pair<std::uint8_t, std::uint64_t> regs[] = {{0x52, 0x0000000200000004ull}, {0x53, 1}};
  pb.ad(regs, true);
  d.packets[0].data = pb.bytes();
  gs::mem::local_memory m;
  interpreter it(m);
  it.replay(d);
  ASSERT_EQ(it.unmodelled_features().size(), 1u);
  EXPECT_EQ(it.unmodelled_features()[0].what, "TRXDIR.XDIR = 1 (local -> host transfer)");
}

// Writes the upload dump where the replay CLI test reads it (GSDOT3_SAMPLE_DUMP), when asked.
TEST(Interpreter, WritesTheSampleDumpForTheCliTest) {
  const char* out = std::getenv("GSDOT3_SAMPLE_DUMP");
  if (out == nullptr) GTEST_SKIP() << "GSDOT3_SAMPLE_DUMP not set";
  dump::save_dump(out, upload_dump());
  EXPECT_EQ(dump::write_dump(dump::load_dump(out)), dump::write_dump(upload_dump()));
}

// Older and newer state blobs (state.hpp state_layout), offsets worked by hand from PCSX2's sizes
// (dump_test.cpp StateLayout): version 8 (and 7) FRAME_1 at 124 + 10 * 8, FRAME_2 at 220 + 10 * 8, memory
// at 364; version 9 61 bytes of m_tr more before the memory (425); version 6 has PRMODE after PRIM and
// TEX2 after each TEX1 (environment 16 u64 from 4, contexts of 13 u64 from 132 and 236, vertex from 340,
// tr.x 380, memory 388); version 4 also 28 bytes after each ZBUF (contexts from 132 and 264, memory 444);
// gsdot3's older version 8 (4194760 bytes: UV and FOG 8 bytes each) memory at 372.
TEST(Interpreter, LoadsStateVersions4To9AtTheirOwnOffsets) {
  struct layout_case {
    std::uint32_t version, size, frame_1, frame_2, memory;
  };
  const layout_case cases[] = {
      {8, 4194752, 124 + 10 * 8, 220 + 10 * 8, 364},      {7, 4194752, 124 + 10 * 8, 220 + 10 * 8, 364},
      {9, 4194752 + 61, 124 + 10 * 8, 220 + 10 * 8, 425}, {6, 4194752 + 24, 132 + 11 * 8, 236 + 11 * 8, 388},
      {4, 4194752 + 80, 132 + 11 * 8, 264 + 11 * 8, 444}, {8, 4194760, 124 + 10 * 8, 220 + 10 * 8, 372},
  };
  for (const layout_case& c : cases) {
    std::vector<std::uint8_t> blob(c.size, 0);
    blob[0] = static_cast<std::uint8_t>(c.version);
    blob[c.frame_1] = 0x11;
    blob[c.frame_2] = 0x22;
    blob[c.memory + 5] = 0x5A;
    gs::mem::local_memory m;
    interpreter it(m);
    it.load_state(blob, c.version);
    EXPECT_EQ(it.reg(0x4C), 0x11u) << c.version;  // FRAME_1
    EXPECT_EQ(it.reg(0x4D), 0x22u) << c.version;  // FRAME_2
    EXPECT_EQ(m.byte(5), 0x5Au) << c.version;
    EXPECT_TRUE(it.unmodelled_features().empty()) << c.version;
  }
  // A size that fits no layout, and an unknown version, are reported and load nothing.
  gs::mem::local_memory m;
  interpreter it(m);
  it.load_state(std::vector<std::uint8_t>(100, 0), 8);
  it.load_state(std::vector<std::uint8_t>(4194760, 0), 10);
  EXPECT_EQ(it.unmodelled_features().size(), 2u);
}

// Local -> local (TRXDIR = 2) runs when TRXDIR is written: the uploaded 4×2 rectangle at (2, 1) copied
// with SBP = DBP = 0, SBW = DBW = 1 (bits 16, 48) to (10, 5): TRXPOS SSAX 2, SSAY 1 (bit 16), DSAX 10
// (bit 32), DSAY 5 (bit 48).
TEST(Interpreter, LocalToLocalCopiesWhenTrxdirIsWritten) {
  dump::gs_dump d = upload_dump();
  packet_builder pb;
  const std::pair<std::uint8_t, std::uint64_t> copy[] = {
      {0x50, 0x0001000000010000ull}, {0x51, 0x0005000A00010002ull}, {0x52, 0x0000000200000004ull}, {0x53, 2}};
  pb.ad(copy, true);
  d.packets.insert(d.packets.begin() + 1, {dump::packet_type::transfer, 2, 0, 0, pb.bytes(), 0});
  gs::mem::local_memory m;
  interpreter it(m, {.skip_unmodelled = true});
  it.replay(dump::read_dump(dump::write_dump(d)));
  const gs::mem::buffer fb{fixed::uint<14>::from_wrapped(0), fixed::uint<6>::from_wrapped(1), gs::mem::psm::PSMCT32};
  for (std::uint32_t y = 0; y < 2; ++y)
    for (std::uint32_t x = 0; x < 4; ++x) EXPECT_EQ(m.read_pixel(fb, 10 + x, 5 + y), 0x11223340u + 4 * y + x);
  EXPECT_EQ(it.transfers().size(), 2u);
}

}  // namespace

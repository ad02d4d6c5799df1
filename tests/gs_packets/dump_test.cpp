// The GS dump container: the header and state blob checked byte by byte against offsets worked out by
// hand from PCSX2 `GSDumpBase::AddHeader` / `GSDumpHeader` / `GSState::Freeze` (see
// src/gs_packets/gs_packets/dump.hpp, state.hpp), round trips through xz and zstd, and one-line errors.
#include <gtest/gtest.h>

#include <filesystem>

#include "gs_packets/builder.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/state.hpp"
#include "common/temp_dir.hpp"

namespace {

using namespace gs::dump;
namespace pk = gs::packets;

std::uint32_t le32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return std::uint32_t{b[at]} | (std::uint32_t{b[at + 1]} << 8) | (std::uint32_t{b[at + 2]} << 16) |
         (std::uint32_t{b[at + 3]} << 24);
}

gs_dump sample() {
  gs_dump d;
  d.crc = 0x12345678;
  d.state_version = 8;
  d.serial = "gsdot3";
  d.screenshot_width = 2;
  d.screenshot_height = 1;
  d.screenshot = {1, 2, 3, 4, 5, 6, 7, 8};
  d.state = make_state_v8();
  state_set(d.state, *state_field_v8("FRAME_1"), 0x000A0000);
  d.privileged[0] = 0x55;
  pk::packet_builder pb;
  const std::pair<std::uint8_t, std::uint64_t> w[] = {{0x53, 0}};
  pb.ad(w);
  const std::uint8_t img[16] = {9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9};
  pb.image(img, true);
  d.packets.push_back({packet_type::transfer, 2, 0, 0, pb.bytes(), 0});
  d.packets.push_back({packet_type::registers, 0, 0, 0, std::vector<std::uint8_t>(privileged_bytes, 0x66), 0});
  d.packets.push_back({packet_type::vsync, 0, 1, 0, {}, 0});
  d.packets.push_back({packet_type::read_fifo2, 0, 0, 7, {}, 0});
  return d;
}

// PCSX2's layout, worked by hand from its declarations (not from state.hpp): GSState::Freeze writes each
// field at its sizeof (pcsx2/GS/GSState.cpp); pcsx2/GS/GSRegs.h is #pragma pack(1) with every GIFReg*
// register a REG64 union of a u64 (8 bytes), GIFTag a REG128 (16), the GIFReg set 8, GIFPath's reg a u32,
// VM_SIZE 4194304; GSVertex.h holds u32 UV and u32 FOG (4 each); GSState.h: float m_q, m_tr's x, y, w, h,
// total, start, end ints (4), rect a GSVector4i (16), m_blit / m_pos / m_reg GIFReg* (8), write a bool (1).
//   version                            0 + 4                          =   4
//   15 environment registers           4 + 15 * 8                     = 124
//   2 contexts of 12 registers       124 + 24 * 8                     = 316
//   RGBAQ 8, ST 8, UV 4, FOG 4, XYZ 8, sizeof(GIFReg) 8:  316 + 40   = 356
//   tr.x, tr.y                       356 + 2 * 4                      = 364
//   version 9 only: w 4, h 4, m_blit 8, m_pos 8, m_reg 8, rect 16, total 4, start 4, end 4, write 1 = 61
//   memory                           364 (v9: 425) + 4194304          = 4194668 (v9: 4194729)
//   4 paths of GIFTag 16 + u32 reg    + 4 * 20                        = 4194748 (v9: 4194809)
//   Q                                 + 4                             = 4194752 (v9: 4194813)
struct pcsx2_field {
  const char* name;
  std::uint32_t v8, v9, size;  // offsets in version 8 and 9
};
constexpr pcsx2_field pcsx2_fields[] = {
    {"version", 0, 0, 4},
    {"PRIM", 4, 4, 8},
    {"TRXREG_obsolete", 4 + 14 * 8, 4 + 14 * 8, 8},
    {"XYOFFSET_1", 124, 124, 8},
    {"FRAME_1", 124 + 10 * 8, 124 + 10 * 8, 8},
    {"ZBUF_2", 124 + 23 * 8, 124 + 23 * 8, 8},
    {"RGBAQ", 316, 316, 8},
    {"ST", 324, 324, 8},
    {"UV", 332, 332, 4},
    {"FOG", 336, 336, 4},
    {"XYZ", 340, 340, 8},
    {"obsolete", 348, 348, 8},
    {"tr.x", 356, 356, 4},
    {"tr.y", 360, 360, 4},
    {"tr.w", 0, 364, 4},
    {"tr.m_blit", 0, 364 + 8, 8},
    {"tr.rect", 0, 364 + 8 + 24, 16},
    {"tr.write", 0, 364 + 8 + 24 + 16 + 12, 1},
    {"memory", 364, 425, 4194304},
    {"path0.tag", 364 + 4194304, 425 + 4194304, 16},
    {"path3.reg", 364 + 4194304 + 3 * 20 + 16, 425 + 4194304 + 3 * 20 + 16, 4},
    {"Q", 4194748, 4194809, 4},
};
constexpr std::uint32_t pcsx2_size_v8 = 4194752, pcsx2_size_v9 = 4194813;

TEST(StateLayout, IsPcsx2sFreezeLayout) {
  EXPECT_EQ(state_size_v8, pcsx2_size_v8);
  EXPECT_EQ(state_size_v9, pcsx2_size_v9);
  for (const std::uint32_t version : {8u, 9u}) {
    const auto fields = state_layout(version, version == 8 ? pcsx2_size_v8 : pcsx2_size_v9);
    ASSERT_TRUE(fields) << version;
    for (const pcsx2_field& want : pcsx2_fields) {
      const state_field* f = find_field(*fields, want.name);
      if (version == 8 && want.v8 == 0 && want.v9 != 0) {
        EXPECT_EQ(f, nullptr) << want.name << " is version 9's";
        continue;
      }
      ASSERT_NE(f, nullptr) << want.name;
      EXPECT_EQ(f->offset, version == 8 ? want.v8 : want.v9) << want.name << " v" << version;
      EXPECT_EQ(f->size, want.size) << want.name;
    }
  }
}

// The blobs written: version, PRMODECONT.AC = 1 and Q = 1.0f at PCSX2's offsets, zero elsewhere.
TEST(StateLayout, WrittenBlobsOfVersions8And9) {
  for (const std::uint32_t version : {8u, 9u}) {
    const auto b = make_state(version);
    const std::uint32_t q = version == 8 ? 4194748 : 4194809;
    ASSERT_EQ(b.size(), version == 8 ? pcsx2_size_v8 : pcsx2_size_v9);
    EXPECT_EQ(le32(b, 0), version);
    EXPECT_EQ(le32(b, 12), 1u);  // PRMODECONT at 4 + 8
    EXPECT_EQ(le32(b, q), 0x3F800000u);
    std::size_t nonzero = 0;
    for (const std::uint8_t v : b) nonzero += v != 0;
    EXPECT_EQ(nonzero, 1u + 1 + 2) << version;  // the version byte, AC, the two top bytes of 1.0f
  }
  EXPECT_EQ(make_state_v8(), make_state(8));
}

TEST(Dump, NewLayoutByteByByte) {
  const auto b = write_dump(sample());
  EXPECT_EQ(le32(b, 0), 0xFFFFFFFFu);
  EXPECT_EQ(le32(b, 4), 36u + 6 + 8);   // header size = GSDumpHeader + serial + screenshot
  EXPECT_EQ(le32(b, 8), 8u);            // state_version
  EXPECT_EQ(le32(b, 12), 4194752u);     // state_size
  EXPECT_EQ(le32(b, 16), 36u);          // serial_offset (from the start of GSDumpHeader)
  EXPECT_EQ(le32(b, 20), 6u);           // serial_size
  EXPECT_EQ(le32(b, 24), 0x12345678u);  // crc
  EXPECT_EQ(le32(b, 28), 2u);
  EXPECT_EQ(le32(b, 32), 1u);
  EXPECT_EQ(le32(b, 36), 42u);  // screenshot_offset = 36 + 6
  EXPECT_EQ(le32(b, 40), 8u);
  EXPECT_EQ(std::string(b.begin() + 44, b.begin() + 50), "gsdot3");
  EXPECT_EQ(b[50], 1);
  EXPECT_EQ(b[57], 8);
  const std::size_t state = 58;
  EXPECT_EQ(le32(b, state), 8u);                     // the blob's own version
  EXPECT_EQ(le32(b, state + 4 + 8), 1u);             // PRMODECONT.AC = 1
  EXPECT_EQ(le32(b, state + 204), 0x000A0000u);      // FRAME_1
  EXPECT_EQ(le32(b, state + 4194748), 0x3F800000u);  // Q = 1.0f
  const std::size_t regs = state + 4194752;
  EXPECT_EQ(b[regs], 0x55);
  const std::size_t pk0 = regs + 8192;
  EXPECT_EQ(b[pk0], 0);                  // transfer
  EXPECT_EQ(b[pk0 + 1], 2);              // PATH3
  EXPECT_EQ(le32(b, pk0 + 2), 16u * 4);  // A+D tag + 1 write, IMAGE tag + 1 qword
  const std::size_t pk1 = pk0 + 6 + 64;
  EXPECT_EQ(b[pk1], 3);
  EXPECT_EQ(b[pk1 + 1], 0x66);
  const std::size_t pk2 = pk1 + 1 + 8192;
  EXPECT_EQ(b[pk2], 1);
  EXPECT_EQ(b[pk2 + 1], 1);
  EXPECT_EQ(b[pk2 + 2], 2);
  EXPECT_EQ(le32(b, pk2 + 3), 7u);
  EXPECT_EQ(b.size(), pk2 + 7);
}

// assign_offsets against the reader (an independent walk of the written bytes), and a dump built in
// memory without it refused by decode_paths instead of replayed in the wrong order.
TEST(Dump, AssignedOffsetsAreWhereTheReaderFindsThePackets) {
  gs_dump d = sample();
  EXPECT_THROW(decode_paths(d), dump_error);
  assign_offsets(d);
  const gs_dump r = read_dump(write_dump(d));
  ASSERT_EQ(r.packets.size(), d.packets.size());
  for (std::size_t i = 0; i < d.packets.size(); ++i) EXPECT_EQ(d.packets[i].offset, r.packets[i].offset) << i;
  EXPECT_EQ(decode_paths(d)[2].file_offsets, decode_paths(r)[2].file_offsets);
}

TEST(Dump, ReadsBackWhatItWrote) {
  const gs_dump d = sample();
  const auto b = write_dump(d);
  const gs_dump r = read_dump(b);
  EXPECT_TRUE(r.new_layout);
  EXPECT_EQ(r.crc, d.crc);
  EXPECT_EQ(r.serial, d.serial);
  EXPECT_EQ(r.screenshot, d.screenshot);
  EXPECT_EQ(r.state, d.state);
  EXPECT_EQ(r.privileged, d.privileged);
  ASSERT_EQ(r.packets.size(), 4u);
  EXPECT_EQ(r.packets[0].data, d.packets[0].data);
  EXPECT_EQ(r.packets[0].offset, 58u + 4194752 + 8192);
  EXPECT_EQ(r.packets[2].field, 1);
  EXPECT_EQ(r.packets[3].size, 7u);
  EXPECT_EQ(write_dump(r), b);
  const auto paths = decode_paths(r);
  EXPECT_EQ(paths[2].events.size(), 4u);  // A+D tag, TRXDIR write, IMAGE tag, image data
  EXPECT_TRUE(paths[0].events.empty());
}

TEST(Dump, ReadsTheOldLayout) {
  // u32 CRC, u32 state size, state, 8 KiB registers, packets (GSDumpBase::AddHeader before the header).
  const gs_dump d = sample();
  std::vector<std::uint8_t> b;
  for (const std::uint32_t v : {0xCAFEF00Du, state_size_v8})
    for (int k = 0; k < 4; ++k) b.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
  b.insert(b.end(), d.state.begin(), d.state.end());
  b.insert(b.end(), d.privileged.begin(), d.privileged.end());
  b.insert(b.end(), {1, 0});  // vsync, field 0
  const gs_dump r = read_dump(b);
  EXPECT_FALSE(r.new_layout);
  EXPECT_EQ(r.crc, 0xCAFEF00Du);
  EXPECT_EQ(r.state_version, 8u);
  EXPECT_EQ(r.state, d.state);
  ASSERT_EQ(r.packets.size(), 1u);
  EXPECT_EQ(r.packets[0].type, packet_type::vsync);
}

TEST(Dump, CompressedRoundTrips) {
  const auto raw = write_dump(sample());
  for (const compression c : {compression::xz, compression::zstd}) {
    const auto z = compress(raw, c);
    EXPECT_LT(z.size(), raw.size() / 100);  // 4 MiB of zero memory
    EXPECT_EQ(decompress(z), raw);
  }
  EXPECT_EQ(compression_for("a.gs.xz"), compression::xz);
  EXPECT_EQ(compression_for("a.gs.zst"), compression::zstd);
  EXPECT_EQ(compression_for("a.gs"), compression::none);
  const auto dir = gsdot3::test::fresh_temp_dir("gsdot3-dump-test");
  for (const char* name : {"t.gs", "t.gs.xz", "t.gs.zst"}) {
    save_dump(dir / name, sample());
    EXPECT_EQ(write_dump(load_dump(dir / name)), raw) << name;
  }
  std::filesystem::remove_all(dir);
}

std::string error_of(const std::vector<std::uint8_t>& b) {
  try {
    const gs_dump d = read_dump(b);
    decode_paths(d);
  } catch (const dump_error& e) { return e.what(); }
  return "no error";
}

// gsdot3 before issue 57 wrote version 8 with UV and FOG 8 bytes each: 4194760 bytes, every field from
// XYZ on 8 bytes further than PCSX2's (the layout docs/dumps.md gave then: XYZ 348, tr.x 364, memory
// 372, path0.tag 4194676, Q 4194756). Such a dump is read in that layout, with a notice.
TEST(Dump, ReadsGsdot3sOlderStateLayoutWithANotice) {
  gs_dump d = sample();
  d.state.assign(4194760, 0);
  d.state[0] = 8;
  d.state[204] = 0x0A;          // FRAME_1, as in PCSX2's layout
  d.state[348] = 0x34;          // XYZ
  d.state[372 + 5] = 0x5A;      // memory byte 5
  d.state[4194676] = 0x77;      // path0.tag
  d.state[4194756 + 3] = 0x3F;  // Q's top byte
  const gs_dump r = read_dump(write_dump(d));
  ASSERT_EQ(r.notices.size(), 1u);
  EXPECT_EQ(r.notices[0].name, "gsdot3_state_layout");
  EXPECT_EQ(r.notices[0].offset, 58u);
  const auto fields = state_layout(8, r.state.size());
  ASSERT_TRUE(fields);
  EXPECT_EQ(state_get(r.state, *find_field(*fields, "FRAME_1")), 0x0Au);
  EXPECT_EQ(state_get(r.state, *find_field(*fields, "XYZ")), 0x34u);
  EXPECT_EQ(find_field(*fields, "memory")->offset, 372u);
  EXPECT_EQ(r.state[find_field(*fields, "memory")->offset + 5], 0x5A);
  EXPECT_EQ(state_get(r.state, *find_field(*fields, "path0.tag")), 0x77u);
  EXPECT_EQ(state_get(r.state, *find_field(*fields, "Q")), 0x3F000000u);
  EXPECT_EQ(write_dump(r), write_dump(d));  // kept as it is
  // PCSX2's own sizes give no notice.
  EXPECT_TRUE(read_dump(write_dump(sample())).notices.empty());
  d.state = make_state(9);
  d.state_version = 9;
  EXPECT_TRUE(read_dump(write_dump(d)).notices.empty());
  // Version 9 of any other size fits no layout.
  d.state.resize(4194760 + 61);
  EXPECT_EQ(error_of(write_dump(d)).rfind("byte 58: state size 4194821 does not fit the version 9 layout", 0), 0u);
}

TEST(Dump, MalformedDumpsGiveOneLineErrors) {
  const auto good = write_dump(sample());
  EXPECT_EQ(error_of({0xFF, 0xFF}), "byte 0: dump header of 4 bytes runs past the end of the dump (2 left)");
  auto bad = good;
  bad[4] = 10;  // header size 10 < 36
  bad[5] = bad[6] = bad[7] = 0;
  EXPECT_EQ(error_of(bad), "byte 4: header size 10 is smaller than GSDumpHeader (36)");
  bad = good;
  bad[12] = 100;  // state_size 100 for version 8
  bad[13] = bad[14] = bad[15] = 0;
  EXPECT_EQ(error_of(bad).rfind("byte 58: state size 100 does not fit the version 8 layout (PCSX2's GSState::Freeze: "
                                "4194752 bytes for version 8, 4194813 for 9; gsdot3's older version 8: 4194760)",
                                0),
            0u)
      << error_of(bad);
  bad = good;
  bad[8] = 99;  // the header's state_version differs from the blob's (8): the blob's is used
  EXPECT_EQ(error_of(bad), "no error");
  bad = good;
  bad[58] = 99;  // the blob's version 99 (and the header's, below): refused as PCSX2's Defrost refuses it
  bad[8] = 99;
  EXPECT_EQ(error_of(bad),
            "byte 58: state version 99: GS: Savestate version is incompatible.  Load aborted. "
            "(PCSX2's GSState::Defrost loads versions 0..9)");
  bad = good;
  bad[16] = 60;  // serial (6 bytes) at 60: outside the 50-byte header
  EXPECT_EQ(error_of(bad),
            "byte 8: serial at 60 (+6) lies outside the header of 50 bytes: GSDump header is corrupted. "
            "(PCSX2 GSDumpFile::ReadFile)");
  bad = good;
  const std::size_t transfer_at = 58 + 4194752 + 8192;
  bad.resize(transfer_at + 3);  // a transfer header cut: refused (ReadFile's GET_WORD fails)
  EXPECT_EQ(error_of(bad), "byte " + std::to_string(transfer_at + 2) +
                               ": transfer size of 4 bytes runs past the end of the dump (1 left)");
  bad = good;
  bad.push_back(9);
  EXPECT_EQ(error_of(bad), "byte " + std::to_string(good.size()) + ": unknown packet type 9 (0..3)");
  // A transfer whose GIF tag claims more data than the path's stream holds: IMAGE NLOOP 5, no data.
  gs_dump d = sample();
  d.packets = {{packet_type::transfer, 1, 0, 0, {5, 0, 0, 0, 0, 0, 0, 0x08, 0, 0, 0, 0, 0, 0, 0, 0}, 0}};
  EXPECT_EQ(error_of(write_dump(d)), "byte " + std::to_string(58 + 4194752 + 8192 + 6) + " (path 1 transfer at byte " +
                                         std::to_string(58 + 4194752 + 8192) +
                                         "): qword 0: GIF tag NLOOP 5 needs 5 data qwords, 0 left");
}

// The leniencies of PCSX2's reader (dump.hpp's notices), one each, with the byte offsets worked out
// from sample(): header 8..58, state 58.., registers, then the transfer (70 bytes), the registers
// packet (8193), the vsync (2), the readFIFO2 (5).

TEST(DumpLeniency, TruncatedLastPacketIsDropped) {
  const auto good = write_dump(sample());
  auto bad = good;
  bad.resize(good.size() - 3);  // the readFIFO2's u32 cut
  const gs_dump d = read_dump(bad);
  ASSERT_EQ(d.notices.size(), 1u);
  EXPECT_EQ(d.notices[0].name, "truncated_last_packet");
  EXPECT_EQ(d.notices[0].offset, good.size() - 5);
  EXPECT_EQ(describe(d.notices[0]),
            "byte " + std::to_string(good.size() - 5) +
                ": truncated_last_packet: the last packet needs 4 bytes, the dump has 1; dropped, "
                "as PCSX2's GSDumpFile::ReadFile does");
  EXPECT_EQ(d.packets.size(), 3u);
  // A transfer whose data is cut: dropped too, the packets before it kept.
  bad = good;
  bad.resize(58 + 4194752 + 8192 + 6 + 20);
  const gs_dump t = read_dump(bad);
  ASSERT_EQ(t.notices.size(), 1u);
  EXPECT_EQ(t.notices[0].offset, 58u + 4194752 + 8192);
  EXPECT_TRUE(t.packets.empty());
}

TEST(DumpLeniency, ScreenshotOfTheWrongSizeIsIgnored) {
  auto bad = write_dump(sample());
  bad[40] = 7;  // screenshot_size 7, not 2 x 1 x 4
  const gs_dump d = read_dump(bad);
  ASSERT_EQ(d.notices.size(), 1u);
  EXPECT_EQ(d.notices[0].name, "screenshot_ignored");
  EXPECT_EQ(d.notices[0].offset, 28u);
  EXPECT_TRUE(d.screenshot.empty());
  EXPECT_EQ(d.screenshot_width, 0u);
  EXPECT_EQ(d.packets.size(), 4u);
  EXPECT_NO_THROW(write_dump(d));
}

TEST(DumpLeniency, TransferPathAbove3IsSkipped) {
  auto bad = write_dump(sample());
  const std::size_t transfer_at = 58 + 4194752 + 8192;
  bad[transfer_at + 1] = 4;
  const gs_dump d = read_dump(bad);
  ASSERT_EQ(d.notices.size(), 1u);
  EXPECT_EQ(d.notices[0].name, "transfer_path_skipped");
  EXPECT_EQ(d.notices[0].offset, transfer_at);
  ASSERT_EQ(d.packets.size(), 3u);
  EXPECT_EQ(d.packets[0].type, packet_type::registers);
  EXPECT_NO_THROW(decode_paths(d));
}

TEST(DumpLeniency, HeaderStateVersionDiffering) {
  auto bad = write_dump(sample());
  bad[8] = 7;
  const gs_dump d = read_dump(bad);
  ASSERT_EQ(d.notices.size(), 1u);
  EXPECT_EQ(d.notices[0].name, "state_version_differs");
  EXPECT_EQ(d.notices[0].offset, 58u);
  EXPECT_EQ(d.state_version, 8u);
}

TEST(DumpLeniency, UnusedRegisterWritesAreCounted) {
  gs_dump d = sample();
  pk::packet_builder pb;
  const std::pair<std::uint8_t, std::uint64_t> w[] = {{0x3F, 0}, {0x7F, 5}, {0x7F, 6}, {0x20, 1}};
  pb.ad(w, true);
  d.packets = {{packet_type::transfer, 2, 0, 0, pb.bytes(), 0}};
  const auto paths = decode_paths(read_dump(write_dump(d)));
  EXPECT_EQ(paths[2].unused_writes, 3u);  // 0x7F twice, 0x20 (no GS register has either)
  EXPECT_EQ(paths[2].first_unused_address, 0x7Fu);
  EXPECT_EQ(paths[2].first_unused_offset, 58u + 4194752 + 8192 + 6 + 32);  // the tag, the TEXFLUSH write, then 0x7F
}

TEST(Dump, CompressionByExtensionIgnoresCase) {
  EXPECT_EQ(compression_for("a.GS.XZ"), compression::xz);
  EXPECT_EQ(compression_for("a.gs.Zst"), compression::zstd);
  EXPECT_EQ(compression_for("a.GS"), compression::none);
}

TEST(Dump, PacketsContinueAcrossTransfers) {
  gs_dump d = sample();
  pk::packet_builder pb;
  std::vector<std::uint8_t> img(64, 3);
  pb.image(img, true);
  const auto all = pb.bytes();  // tag + 4 qwords, split after the second data qword
  d.packets = {{packet_type::transfer, 2, 0, 0, {all.begin(), all.begin() + 48}, 0},
               {packet_type::vsync, 0, 0, 0, {}, 0},
               {packet_type::transfer, 2, 0, 0, {all.begin() + 48, all.end()}, 0}};
  const auto paths = decode_paths(read_dump(write_dump(d)));
  ASSERT_EQ(paths[2].events.size(), 2u);
  EXPECT_EQ(paths[2].events[1].data.size(), 64u);
}

}  // namespace

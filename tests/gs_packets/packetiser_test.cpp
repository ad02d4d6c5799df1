// split_gif_packets (gs_packets/packetiser.hpp): every packet within the bound, whole tags, EOP on its
// last tag only, cuts at primitive boundaries, and the register writes of the packets in order equal
// the unsplit stream's (decoded by decode_gif, the reference). Packet counts worked out by hand.
#include <gtest/gtest.h>

#include <stdexcept>
#include <utility>
#include <vector>

#include "gs_packets/builder.hpp"
#include "gs_packets/decoder.hpp"
#include "gs_packets/packetiser.hpp"

namespace {

namespace pk = gs::packets;
using writes = std::vector<std::pair<std::uint8_t, std::uint64_t>>;

writes writes_of(const std::vector<std::uint8_t>& bytes) {
  writes w;
  for (const auto& e : pk::decode_gif(bytes))
    if (e.what == pk::gif_event::kind::reg_write) w.emplace_back(e.address, e.value);
  return w;
}

// Per packet: at most max bytes, decodes alone (whole tags), EOP on the last tag and on no other.
void expect_packets(const std::vector<std::vector<std::uint8_t>>& packets, std::size_t max) {
  for (const auto& p : packets) {
    EXPECT_LE(p.size(), max);
    const auto events = pk::decode_gif(p);
    std::vector<bool> eops;
    for (const auto& e : events)
      if (e.what == pk::gif_event::kind::tag) eops.push_back(e.tag.EOP);
    ASSERT_FALSE(eops.empty());
    EXPECT_TRUE(eops.back());
    for (std::size_t i = 0; i + 1 < eops.size(); ++i) EXPECT_FALSE(eops[i]) << "tag " << i;
  }
}

std::vector<std::uint8_t> concat(const std::vector<std::vector<std::uint8_t>>& packets) {
  std::vector<std::uint8_t> all;
  for (const auto& p : packets) all.insert(all.end(), p.begin(), p.end());
  return all;
}

// n triangles as one PACKED tag {RGBAQ, UV, XYZ2}, PRE with PRIM = TRIANGLE (3).
pk::packet_builder triangles(unsigned n, unsigned prim = 3) {
  std::vector<pk::qword> data;
  for (unsigned v = 0; v < 3 * n; ++v) {
    data.push_back(pk::packed_rgba(v & 0xFF, 1, 2, 3));
    data.push_back(pk::packed_uv(v, v));
    data.push_back(pk::packed_xyz2(static_cast<std::uint16_t>(v), 7, v, false));
  }
  const unsigned regs[] = {pk::desc::RGBAQ, pk::desc::UV, pk::desc::XYZ2};
  pk::packet_builder b;
  b.packed(prim, regs, data);
  return b;
}

TEST(Packetiser, TrianglesAreCutAtWholeTriangles) {
  const auto b = triangles(1000);  // NLOOP 3000, 9000 data qwords
  const auto packets = pk::split_gif_packets(b.bytes(), 4096);
  // 4096 bytes = 256 qwords: a tag and 255 data qwords = 85 loops, cut at a multiple of 3 vertices:
  // 84 loops (28 triangles) per packet, 3000 / 84 = 35 full packets and one of 60 loops.
  ASSERT_EQ(packets.size(), 36u);
  expect_packets(packets, 4096);
  for (std::size_t i = 0; i < packets.size(); ++i) {
    const auto events = pk::decode_gif(packets[i]);
    EXPECT_EQ(events[0].tag.NLOOP.value(), i + 1 < packets.size() ? 84u : 60u);
    EXPECT_EQ(events[0].tag.PRE, i == 0);  // PRIM written once, by the first part
  }
  EXPECT_EQ(writes_of(concat(packets)), writes_of(b.bytes()));
}

TEST(Packetiser, StripsAreCutAfterTheirFirstTriangleListsAtWholeTriangles) {
  // 208 bytes = 13 qwords: a tag and 12 data qwords = 4 vertices. A TRIANGLE list (3) is cut after
  // vertex 3; a TRIANGLE_STRIP (4) after vertex 4 (every vertex from the third ends a triangle).
  const auto list = pk::split_gif_packets(triangles(2, 3).bytes(), 208);
  const auto strip = pk::split_gif_packets(triangles(2, 4).bytes(), 208);
  ASSERT_EQ(list.size(), 2u);
  ASSERT_EQ(strip.size(), 2u);
  EXPECT_EQ(pk::decode_gif(list[0])[0].tag.NLOOP.value(), 3u);
  EXPECT_EQ(pk::decode_gif(strip[0])[0].tag.NLOOP.value(), 4u);
  EXPECT_EQ(writes_of(concat(strip)), writes_of(triangles(2, 4).bytes()));
  // 128 bytes: room for 2 vertices, which end no triangle of a strip: no cut.
  EXPECT_THROW(pk::split_gif_packets(triangles(2, 4).bytes(), 128), std::invalid_argument);
}

TEST(Packetiser, ImagesAreCutAtAnyQwordAndSmallTagsShareAPacket) {
  pk::packet_builder b;
  const writes ad = {{0x50, 1}, {0x51, 2}, {0x52, 3}, {0x53, 0}};
  b.ad(ad);  // 5 qwords
  std::vector<std::uint8_t> image(16 * 6400, 0x5A);
  b.image(image);  // one tag of 6400 qwords
  const auto packets = pk::split_gif_packets(b.bytes(), 16 * 1024);
  // The A+D tag (5 qwords) and 1018 image qwords fill the first packet (5 + 1 + 1018 = 1024); then
  // 5382 qwords in parts of 1023: 5 full packets and one of 267.
  ASSERT_EQ(packets.size(), 7u);
  EXPECT_EQ(packets[0].size(), 16u * 1024);
  EXPECT_EQ(packets.back().size(), 16u * 268);
  expect_packets(packets, 16 * 1024);
  std::size_t image_bytes = 0;
  for (const auto& p : packets)
    for (const auto& e : pk::decode_gif(p))
      if (e.what == pk::gif_event::kind::image) image_bytes += e.data.size();
  EXPECT_EQ(image_bytes, image.size());
  EXPECT_EQ(writes_of(concat(packets)), writes_of(b.bytes()));
  // Whole: one packet.
  EXPECT_EQ(pk::split_gif_packets(b.bytes()).size(), 1u);
}

TEST(Packetiser, AnInputEopEndsAPacket) {
  pk::packet_builder b;
  const writes one = {{0x3F, 0}};
  b.ad(one, true);
  b.ad(one);
  b.ad(one);
  const auto packets = pk::split_gif_packets(b.bytes());
  ASSERT_EQ(packets.size(), 2u);
  EXPECT_EQ(packets[0].size(), 32u);
  EXPECT_EQ(packets[1].size(), 64u);
  expect_packets(packets, 64);
}

TEST(Packetiser, RefusesWhatCannotBeCut) {
  EXPECT_THROW(pk::split_gif_packets(triangles(1).bytes(), 16), std::invalid_argument);  // under 32 bytes
  // A triangle needs 9 data qwords; 8 qwords of room (128 bytes) hold no whole triangle.
  EXPECT_THROW(pk::split_gif_packets(triangles(2).bytes(), 128), std::invalid_argument);
  EXPECT_THROW(pk::split_gif_packets(std::vector<std::uint8_t>(8, 0)), std::invalid_argument);  // not whole qwords
}

}  // namespace

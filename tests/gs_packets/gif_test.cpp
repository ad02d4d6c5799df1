// GIF tags, PACKED forms and the packet decoder against qwords assembled by hand from the field layout
// of PCSX2 `pcsx2/GS/GSRegs.h` (`union GIFTag`, `REG128_(GIFPacked, …)`, `REG64_(GIFReg, …)`), which
// transcribes the GS User's Manual. Each expected constant is worked out in the comment beside it.
#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include "gs_packets/builder.hpp"
#include "gs_packets/decoder.hpp"
#include "gs_packets/gif_tag.hpp"
#include "gs_packets/gs_registers.hpp"

namespace {

using namespace gs::packets;

std::vector<std::uint8_t> bytes_of(std::initializer_list<qword> qs) {
  std::vector<std::uint8_t> out;
  for (const qword& w : qs)
    for (const std::uint64_t v : {w.lo, w.hi})
      for (int b = 0; b < 8; ++b) out.push_back(static_cast<std::uint8_t>(v >> (8 * b)));
  return out;
}

// NLOOP 1 | EOP 1<<15 | PRE 1<<46 | PRIM 6<<47 (= 3<<48) | FLG 0 | NREG 3<<60 ; REGS 1 | 3<<4 | 5<<8.
constexpr qword sprite_tag{0x3003400000008001ull, 0x531ull};

TEST(GifTag, DecodesHandAssembledTag) {
  constexpr auto t = decode_gif_tag(sprite_tag);
  static_assert(t.has_value());
  static_assert(t->NLOOP.value() == 1 && t->EOP && t->PRE && t->PRIM.value() == 6 && t->FLG == gif_flg::PACKED);
  static_assert(t->NREG.value() == 3 && t->REGS[0].value() == 1 && t->REGS[1].value() == 3 && t->REGS[2].value() == 5);
  static_assert(encode(*t) == sprite_tag);
  EXPECT_EQ(t->registers(), 3u);
}

TEST(GifTag, Nreg0Means16AndFlg3IsRefused) {
  constexpr qword t16{0x0000000000000001ull, 0xFEDCBA9876543210ull};
  static_assert(decode_gif_tag(t16)->registers() == 16);
  static_assert(decode_gif_tag(t16)->REGS[15].value() == 0xF);
  static_assert(!decode_gif_tag({0x0C00000000000000ull, 0}).has_value());  // FLG = 3 << 58
}

TEST(GifTag, RoundTripClearsOnlyTheUnusedBits) {
  std::mt19937_64 rng(15);
  constexpr std::uint64_t unused = ((std::uint64_t{1} << 30) - 1) << 16;  // bits 16-45
  for (int i = 0; i < 100000; ++i) {
    const qword q{rng(), rng()};
    const auto t = decode_gif_tag(q);
    if (((q.lo >> 58) & 3) == 3) {
      EXPECT_FALSE(t.has_value());
      continue;
    }
    ASSERT_TRUE(t.has_value());
    const qword back = encode(*t);
    ASSERT_EQ(back.lo, q.lo & ~unused) << std::hex << q.lo;
    ASSERT_EQ(back.hi, q.hi);
  }
}

TEST(Decoder, PackedVertexWithPre) {
  // RGBA R 0x11 G 0x22 B 0x33 A 0x44: G at bit 32, B at bit 64, A at bit 96.
  // UV U 0x1234 V 0x0ABC: V at bit 32.  XYZ2 X 0x8000 Y 0x8100 Z 0x10: Y at bit 32, Z at bit 64.
  const auto b = bytes_of({sprite_tag,
                           {0x0000002200000011ull, 0x0000004400000033ull},
                           {0x00000ABC00001234ull, 0},
                           {0x0000810000008000ull, 0x10}});
  const auto ev = decode_gif(b);
  ASSERT_EQ(ev.size(), 5u);
  EXPECT_EQ(ev[0].what, gif_event::kind::tag);
  // PRE: PRIM = 6 from the tag, at the tag's offset.
  EXPECT_EQ(ev[1].what, gif_event::kind::reg_write);
  EXPECT_EQ(ev[1].address, 0x00);
  EXPECT_EQ(ev[1].value, 6u);
  EXPECT_EQ(ev[1].offset, 0u);
  // RGBAQ: R | G<<8 | B<<16 | A<<24 | Q<<32 with Q = 1.0f (0x3F800000) before any ST.
  EXPECT_EQ(ev[2].address, 0x01);
  EXPECT_EQ(ev[2].value, 0x3F80000044332211ull);
  EXPECT_EQ(ev[2].offset, 1u);
  // UV: U | V<<16.
  EXPECT_EQ(ev[3].address, 0x03);
  EXPECT_EQ(ev[3].value, 0x0ABC1234ull);
  // XYZ2: X | Y<<16 | Z<<32.
  EXPECT_EQ(ev[4].address, 0x05);
  EXPECT_EQ(ev[4].value, 0x0000001081008000ull);
  EXPECT_EQ(ev[4].offset, 3u);
}

TEST(Decoder, XyzF2WithAdcGoesToXyzF3AndStSetsQ) {
  // Tag: NLOOP 1, NREG 3 (3<<60), REGS ST 2 | RGBAQ 1<<4 | XYZF2 4<<8.
  const qword tag{0x3000000000000001ull, 0x412ull};
  // ST S 0x40000000 T 0x3F000000 Q 0x3E800000 (Q at bit 64).
  // XYZF2 X 0x10 Y 0x20 Z 0xABCDEF (bit 68) F 0x7F (bit 100) ADC 1 (bit 111):
  //   hi = 0xABCDEF<<4 | 0x7F<<36 | 1<<47 = 0x000087F00ABCDEF0.
  const auto b = bytes_of(
      {tag, {0x3F00000040000000ull, 0x3E800000ull}, {0xFFull, 0}, {0x0000002000000010ull, 0x000087F00ABCDEF0ull}});
  const auto ev = decode_gif(b);
  ASSERT_EQ(ev.size(), 4u);
  EXPECT_EQ(ev[1].address, 0x02);
  EXPECT_EQ(ev[1].value, 0x3F00000040000000ull);
  EXPECT_EQ(ev[2].value, 0x3E800000000000FFull);  // Q from the ST just before
  EXPECT_EQ(ev[3].address, 0x0C);                 // XYZF3: ADC = 1
  EXPECT_EQ(ev[3].value, 0x7FABCDEF00200010ull);  // X | Y<<16 | Z<<32 | F<<56
}

TEST(Decoder, AdReglistImage) {
  // A+D: NLOOP 2 | EOP | NREG 1<<60, REGS A+D = 0xE. FRAME_1 (0x4C) FBW 10 at bit 16 = 0xA0000; TRXDIR (0x53) 0.
  const qword ad_tag{0x1000000000008002ull, 0xEull};
  // REGLIST: NLOOP 1 | FLG 1<<58 | NREG 3<<60, REGS PRIM 0 | RGBAQ 1<<4 | XYZ2 5<<8 = 0x510; 3 values in 2 qwords.
  const qword rl_tag{0x3400000000000001ull, 0x510ull};
  // IMAGE: NLOOP 2 | EOP | FLG 2<<58.
  const qword im_tag{0x0800000000008002ull, 0};
  const auto b = bytes_of({ad_tag,
                           {0xA0000ull, 0x4C},
                           {0, 0x53},
                           rl_tag,
                           {0x6, 0x3F800000FF0000FFull},
                           {0x0000001000200010ull, 0},
                           im_tag,
                           {0x0706050403020100ull, 0x0F0E0D0C0B0A0908ull},
                           {0x1716151413121110ull, 0x1F1E1D1C1B1A1918ull}});
  const auto ev = decode_gif(b);
  ASSERT_EQ(ev.size(), 9u);
  EXPECT_EQ(ev[1].address, 0x4C);
  EXPECT_EQ(ev[1].value, 0xA0000u);
  EXPECT_EQ(ev[2].address, 0x53);
  EXPECT_EQ(ev[2].offset, 2u);
  EXPECT_EQ(ev[3].what, gif_event::kind::tag);
  EXPECT_EQ(ev[3].offset, 3u);
  EXPECT_EQ(ev[4].address, 0x00);
  EXPECT_EQ(ev[4].value, 6u);
  EXPECT_EQ(ev[5].address, 0x01);
  EXPECT_EQ(ev[5].value, 0x3F800000FF0000FFull);
  EXPECT_EQ(ev[5].offset, 4u);
  EXPECT_EQ(ev[6].address, 0x05);
  EXPECT_EQ(ev[6].offset, 5u);
  EXPECT_EQ(ev[7].offset, 6u);
  EXPECT_EQ(ev[8].what, gif_event::kind::image);
  EXPECT_EQ(ev[8].offset, 7u);
  ASSERT_EQ(ev[8].data.size(), 32u);
  for (unsigned i = 0; i < 32; ++i) EXPECT_EQ(ev[8].data[i], i);
}

TEST(Decoder, MalformedInputNamesTheOffset) {
  auto message = [](const std::vector<std::uint8_t>& b) {
    try {
      decode_gif(b);
    } catch (const packet_error& e) { return std::string(e.what()); }
    return std::string("no error");
  };
  // IMAGE NLOOP 2 with one data qword, after one complete NLOOP-0 tag.
  EXPECT_EQ(message(bytes_of({{0, 0}, {0x0800000000000002ull, 0}, {0, 0}})),
            "qword 1: GIF tag NLOOP 2 needs 2 data qwords, 1 left");
  EXPECT_EQ(message(bytes_of({{0x0C00000000000000ull, 0}})), "qword 0: GIF tag FLG 3 (disabled) is not a known mode");
  auto b = bytes_of({{0, 0}});
  b.resize(20);
  EXPECT_EQ(message(b), "byte 16: truncated qword (4 of 16 bytes)");
}

TEST(Builder, WhatItBuildsDecodesToTheSameWrites) {
  packet_builder pb;
  const std::pair<std::uint8_t, std::uint64_t> env[] = {{0x4C, 0x000A0000}, {0x50, 0x0002000000000000ull}, {0x53, 0}};
  pb.ad(env);
  const unsigned descs[] = {desc::RGBAQ, desc::UV, desc::XYZ2};
  const qword verts[] = {packed_rgba(1, 2, 3, 4), packed_uv(0x3FFF, 7), packed_xyz2(0x100, 0x200, 9, false),
                         packed_rgba(5, 6, 7, 8), packed_uv(1, 2),      packed_xyz2(0x300, 0x400, 10, true)};
  pb.packed(6u, descs, verts);
  const unsigned rl[] = {desc::PRIM, desc::RGBAQ, desc::XYZ2};
  const std::uint64_t vals[] = {3, 0x3F80000001020304ull, 0x0000000500060007ull};
  pb.reglist(rl, vals);
  std::vector<std::uint8_t> img(40);
  for (std::size_t i = 0; i < img.size(); ++i) img[i] = static_cast<std::uint8_t>(i * 7);
  pb.image(img, true);
  const auto stream = pb.bytes();  // image events point into it
  const auto ev = decode_gif(stream);
  std::vector<std::pair<std::uint8_t, std::uint64_t>> w;
  std::vector<std::uint8_t> data;
  for (const auto& e : ev) {
    if (e.what == gif_event::kind::reg_write) w.emplace_back(e.address, e.value);
    if (e.what == gif_event::kind::image) data.assign(e.data.begin(), e.data.end());
  }
  const std::vector<std::pair<std::uint8_t, std::uint64_t>> expect = {{0x4C, 0x000A0000},
                                                                      {0x50, 0x0002000000000000ull},
                                                                      {0x53, 0},
                                                                      {0x00, 6},
                                                                      {0x01, 0x3F80000004030201ull},
                                                                      {0x03, 0x00073FFF},
                                                                      {0x05, 0x0000000902000100ull},
                                                                      {0x01, 0x3F80000008070605ull},
                                                                      {0x03, 0x00020001},
                                                                      {0x0D, 0x0000000A04000300ull},  // ADC -> XYZ3
                                                                      {0x00, 3},
                                                                      {0x01, 0x3F80000001020304ull},
                                                                      {0x05, 0x0000000500060007ull}};
  EXPECT_EQ(w, expect);
  ASSERT_EQ(data.size(), 48u);  // 40 bytes padded to 3 qwords
  for (std::size_t i = 0; i < 48; ++i) EXPECT_EQ(data[i], i < 40 ? img[i] : 0);
}

TEST(Builder, ImageSplitsAt32767Qwords) {
  packet_builder pb;
  std::vector<std::uint8_t> img(16 * 32768 + 1, 0xAB);  // 32769 qwords
  pb.image(img, true);
  const auto stream = pb.bytes();  // image events point into it
  const auto ev = decode_gif(stream);
  std::vector<std::size_t> sizes;
  bool eop_last = false;
  for (const auto& e : ev) {
    if (e.what == gif_event::kind::image) sizes.push_back(e.data.size() / 16);
    if (e.what == gif_event::kind::tag) eop_last = e.tag.EOP;
  }
  EXPECT_EQ(sizes, (std::vector<std::size_t>{32767, 2}));
  EXPECT_TRUE(eop_last);
}

TEST(Registers, NamesAndAddresses) {
  static_assert(gs_register_address("FRAME_1") == 0x4C);
  static_assert(gs_register_address("TRXDIR") == 0x53);
  static_assert(gs_register_name_of(0x46) == "COLCLAMP");
  static_assert(!gs_register_name_of(0x0B).has_value());
}

}  // namespace

// ZBUF_1's strict decoder and encoder (gs_arith/registers.hpp) against the GS User's Manual layout
// ZBP bits 0-8, PSM bits 24-27 (0 PSMZ32, 1 PSMZ24, 2 PSMZ16, 0xA PSMZ16S), ZMSK bit 32, every other
// bit reserved: words computed by hand from that layout, fields read back by shifts, the round trip
// on random values, and the strict decoder's refusal of every reserved bit and PSM value. The field
// mask is PCSX2's `GSState.h` ZBUF_REG_MASK 0x10F0001FF (the same three fields).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>

#include "gs_arith/registers.hpp"

namespace {

using gs::zbuf_psm;
using gs::zbuf_reg;

constexpr std::uint64_t field_mask = 0x10F0001FFull;

zbuf_reg z(unsigned zbp, zbuf_psm psm, bool zmsk) { return {fixed::uint<9>::from_wrapped(zbp), psm, zmsk}; }

TEST(ZbufRegister, EncodesTheManualsLayout) {
  // (ZBP, PSM, ZMSK) -> the 64-bit word, by hand: ZBP | PSM << 24 | ZMSK << 32.
  EXPECT_EQ(gs::encode(z(0x150, zbuf_psm::PSMZ24, false)), 0x0000000001000150ull);  // 336 = 3P at 512x448
  EXPECT_EQ(gs::encode(z(0x1FF, zbuf_psm::PSMZ16S, true)), 0x000000010A0001FFull);
  EXPECT_EQ(gs::encode(z(0, zbuf_psm::PSMZ32, true)), 0x0000000100000000ull);
  EXPECT_EQ(gs::encode(z(200, zbuf_psm::PSMZ16, false)), 0x00000000020000C8ull);
  EXPECT_EQ(gs::encode(zbuf_reg{}), 0u);
}

TEST(ZbufRegister, DecodesTheManualsLayout) {
  EXPECT_EQ(gs::decode_zbuf(0x0000000001000150ull), z(0x150, zbuf_psm::PSMZ24, false));
  EXPECT_EQ(gs::decode_zbuf(0x000000010A0001FFull), z(0x1FF, zbuf_psm::PSMZ16S, true));
  EXPECT_EQ(gs::decode_zbuf(0x0000000100000000ull), z(0, zbuf_psm::PSMZ32, true));
  EXPECT_EQ(gs::decode_zbuf(0x00000000020000C8ull), z(200, zbuf_psm::PSMZ16, false));
}

// Random words inside the field mask with a Z format: the fields are the word's bits read by shifts,
// and encode gives the word back; random registers survive encode -> decode.
TEST(ZbufRegister, RoundTripOnRandomValues) {
  std::mt19937_64 rng(0x2B0F);
  const zbuf_psm formats[] = {zbuf_psm::PSMZ32, zbuf_psm::PSMZ24, zbuf_psm::PSMZ16, zbuf_psm::PSMZ16S};
  const std::uint64_t psm_codes[] = {0x0, 0x1, 0x2, 0xA};
  for (int i = 0; i < 100000; ++i) {
    const std::uint64_t r = rng();
    const std::uint64_t v = (r & field_mask & ~(0xFull << 24)) | psm_codes[r >> 62] << 24;
    const zbuf_reg d = gs::decode_zbuf(v);
    ASSERT_EQ(static_cast<std::uint64_t>(d.ZBP.value()), v & 0x1FF) << std::hex << v;
    ASSERT_EQ(static_cast<std::uint64_t>(d.PSM), (v >> 24) & 0xF) << std::hex << v;
    ASSERT_EQ(d.ZMSK, ((v >> 32) & 1) != 0) << std::hex << v;
    ASSERT_EQ(gs::encode(d), v);
    const zbuf_reg reg = z(static_cast<unsigned>(r & 0x1FF), formats[(r >> 20) & 3], ((r >> 40) & 1) != 0);
    ASSERT_EQ(gs::decode_zbuf(gs::encode(reg)), reg);
    ASSERT_EQ(gs::encode(reg) & ~field_mask, 0u);
  }
}

// Strict: any bit outside ZBP, PSM, ZMSK set, or a PSM that is no Z format, throws gs::register_error
// naming ZBUF_1 (and the field for a bad PSM).
TEST(ZbufRegister, StrictDecodeRefusesReservedBitsAndFormats) {
  const std::uint64_t valid = 0x0000000101000150ull;
  int refused = 0;
  for (int b = 0; b < 64; ++b) {
    const std::uint64_t bit = std::uint64_t{1} << b;
    if ((field_mask & bit) != 0) continue;
    try {
      gs::decode_zbuf(valid | bit);
      ADD_FAILURE() << "bit " << b << " accepted";
    } catch (const gs::register_error& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("ZBUF_1"), std::string::npos) << m;
      EXPECT_NE(m.find("reserved bits"), std::string::npos) << m;
      ++refused;
    }
  }
  EXPECT_EQ(refused, 64 - 14);  // 9 + 4 + 1 field bits
  for (std::uint64_t psm = 0; psm < 16; ++psm) {
    const std::uint64_t v = (valid & ~(0xFull << 24)) | psm << 24;
    if (psm == 0x0 || psm == 0x1 || psm == 0x2 || psm == 0xA) {
      EXPECT_NO_THROW(gs::decode_zbuf(v)) << psm;
      continue;
    }
    try {
      gs::decode_zbuf(v);
      ADD_FAILURE() << "PSM " << psm << " accepted";
    } catch (const gs::register_error& e) {
      EXPECT_NE(std::string(e.what()).find("ZBUF_1.PSM"), std::string::npos) << e.what();
    }
  }
}

}  // namespace

// Unit tests of transfers, CLUT loads, CLAMP_1 wrap modes and their registers, each against a
// construction written another way (unpacking by hand, the manual's CSM1 description, modular
// arithmetic and std::clamp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "formats.hpp"
#include "gs_memory/clut_load.hpp"
#include "gs_memory/memory_registers.hpp"
#include "gs_memory/texture_wrap.hpp"
#include "gs_memory/transfer.hpp"

namespace gs::mem {
namespace {

template <int N>
fixed::uint<N> u(std::uint32_t v) {
  return fixed::uint<N>::from_wrapped(v);
}

TEST(GsMemoryRegisters, FieldPositionsByHand) {
  const auto b = decode_bitbltbuf(std::uint64_t{0x1234} << 32 | std::uint64_t{10} << 48 | std::uint64_t{0x13} << 56 |
                                  0x0fffu | std::uint64_t{3} << 16 | std::uint64_t{0x02} << 24);
  EXPECT_EQ(b.DBP.value(), 0x1234);
  EXPECT_EQ(b.DBW.value(), 10);
  EXPECT_EQ(b.DPSM, psm::PSMT8);
  EXPECT_EQ(b.SBP.value(), 0xfff);
  EXPECT_EQ(b.SBW.value(), 3);
  EXPECT_EQ(b.SPSM, psm::PSMCT16);
  const auto p = decode_trxpos(std::uint64_t{5} | std::uint64_t{6} << 16 | std::uint64_t{2047} << 32 |
                               std::uint64_t{8} << 48 | std::uint64_t{3} << 59);
  EXPECT_EQ(p.SSAX.value(), 5);
  EXPECT_EQ(p.SSAY.value(), 6);
  EXPECT_EQ(p.DSAX.value(), 2047);
  EXPECT_EQ(p.DSAY.value(), 8);
  EXPECT_EQ(p.DIR.value(), 3);
  const auto r = decode_trxreg(std::uint64_t{4095} | std::uint64_t{7} << 32);
  EXPECT_EQ(r.RRW.value(), 4095);
  EXPECT_EQ(r.RRH.value(), 7);
  EXPECT_EQ(decode_trxdir(2).XDIR, xdir::local_to_local);
  const auto c = decode_clamp(3u | 1u << 2 | 0x3ffu << 4 | std::uint64_t{5} << 14 | std::uint64_t{6} << 24 |
                              std::uint64_t{0x200} << 34);
  EXPECT_EQ(c.WMS, wrap_mode::REGION_REPEAT);
  EXPECT_EQ(c.WMT, wrap_mode::CLAMP);
  EXPECT_EQ(c.MINU.value(), 0x3ff);
  EXPECT_EQ(c.MAXU.value(), 5);
  EXPECT_EQ(c.MINV.value(), 6);
  EXPECT_EQ(c.MAXV.value(), 0x200);
}

TEST(GsMemoryRegisters, ReservedBitsAndUnknownFormatsAreErrors) {
  EXPECT_THROW(decode_bitbltbuf(std::uint64_t{1} << 14), register_error);     // padding
  EXPECT_THROW(decode_bitbltbuf(std::uint64_t{0x03} << 56), register_error);  // DPSM 3
  EXPECT_THROW(decode_trxpos(std::uint64_t{1} << 11), register_error);
  EXPECT_THROW(decode_trxpos(std::uint64_t{1} << 61), register_error);
  EXPECT_THROW(decode_trxreg(std::uint64_t{1} << 12), register_error);
  EXPECT_THROW(decode_trxdir(4), register_error);
  EXPECT_THROW(decode_clamp(std::uint64_t{1} << 44), register_error);
}

TEST(GsMemoryRegisters, EncodeInvertsDecode) {
  std::mt19937_64 rng(3);
  const std::uint64_t bitblt_fields =
      0x3f3fbfff3f3f3fffull & ~(std::uint64_t{0xc0} << 56) & ~(std::uint64_t{0xc0} << 24);
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t v = rng();
    auto keep = [&](auto decode, std::uint64_t mask) {
      try {
        const auto r = decode(v & mask);
        EXPECT_EQ(encode(r), v & mask);
      } catch (const register_error&) {  // an unknown PSM: the only error inside the field mask
      }
    };
    keep(decode_bitbltbuf, bitblt_fields);
    keep(decode_trxpos, 0x1fff07ff07ff07ffull);
    keep(decode_trxreg, 0x00000fff00000fffull);
    keep(decode_trxdir, 3);
    keep(decode_clamp, 0x00000fffffffffffull);
  }
}

using test::unpack;

TEST(GsMemoryTransfer, HostToLocalWritesTheRectangleAndNothingElse) {
  std::mt19937 rng(11);
  for (const psm p : test::all_psms) {
    local_memory m;
    for (std::uint32_t a = 0; a < 64 * 1024; ++a) m.set_byte(a, 0xA5);
    const bitbltbuf_reg b{u<14>(0), u<6>(0), psm::PSMCT32, u<14>(37), u<6>(2), p};
    const trxpos_reg pos{u<11>(0), u<11>(0), u<11>(9), u<11>(5), u<2>(0)};
    const trxreg_reg reg{u<12>(22), u<12>(13)};
    std::vector<std::uint8_t> data(transfer_bytes(p, 22, 13));
    for (auto& d : data) d = static_cast<std::uint8_t>(rng());
    host_to_local(m, b, pos, reg, trxdir_reg{}, data);
    const buffer dst{u<14>(37), u<6>(2), p};
    std::vector<bool> touched(64 * 1024 * 2, false);  // nibbles
    for (std::uint32_t y = 0; y < 13; ++y)
      for (std::uint32_t x = 0; x < 22; ++x) {
        ASSERT_EQ(m.read_pixel(dst, 9 + x, 5 + y), unpack(data, value_bits(p), y * 22 + x)) << static_cast<int>(p);
        const location at = locate(dst, 9 + x, 5 + y);
        for (unsigned n = 0; n < at.bits / 4; ++n) touched[(at.byte * 8 + at.bit) / 4 + n] = true;
      }
    for (std::uint32_t n = 0; n < touched.size(); ++n)
      if (!touched[n]) {
        ASSERT_EQ((m.byte(n / 2) >> (4 * (n % 2))) & 0xF, n % 2 ? 0xAu : 0x5u) << static_cast<int>(p);
      }
    EXPECT_THROW(host_to_local(m, b, pos, reg, trxdir_reg{}, std::vector<std::uint8_t>(data.size() + 1)),
                 std::invalid_argument);
    EXPECT_THROW(host_to_local(m, b, pos, reg, trxdir_reg{xdir::local_to_local}, data), std::invalid_argument);
  }
}

// The manual's CSM1 description, written by hand: within each 32 entries, 0-7 on row 0 left, 8-15 on
// row 1 left, 16-23 row 0 right, 24-31 row 1 right; each next 32 entries two rows lower.
std::pair<std::uint32_t, std::uint32_t> csm1_xy(std::uint32_t i) {
  const std::uint32_t k = i % 32;
  return {(k / 16) * 8 + k % 8, 2 * (i / 32) + (k / 8) % 2};
}

// The formats host_to_local stores unit by unit (PSMCT32, PSMZ32, PSMT8) against the generic write:
// each host value unpacked by hand and written by write_pixel into a second memory, which must equal
// the first everywhere (4 MiB). Random rectangles, DBP over the whole range (so the 4 MiB wrap is
// crossed), DBW 0..63 and DSAX/DSAY up to the 2048 limit, 300 per format.
TEST(GsMemoryTransfer, WholeUnitFormatsEqualTheGenericWrite) {
  std::mt19937 rng(5);
  for (const psm p : {psm::PSMCT32, psm::PSMZ32, psm::PSMT8})
    for (int i = 0; i < 300; ++i) {
      const std::uint32_t w = 1 + rng() % 80, h = 1 + rng() % 40;
      const std::uint32_t x0 = rng() % (2049 - w), y0 = rng() % (2049 - h);
      const bitbltbuf_reg b{u<14>(0), u<6>(0), psm::PSMCT32, u<14>(rng()), u<6>(rng()), p};
      const trxpos_reg pos{u<11>(0), u<11>(0), u<11>(x0), u<11>(y0), u<2>(0)};
      std::vector<std::uint8_t> data(transfer_bytes(p, w, h));
      for (auto& d : data) d = static_cast<std::uint8_t>(rng());
      local_memory fast, generic;
      for (std::uint32_t a = 0; a < memory_bytes; a += 4093) fast.set_byte(a, 0x5A), generic.set_byte(a, 0x5A);
      host_to_local(fast, b, pos, trxreg_reg{u<12>(w), u<12>(h)}, trxdir_reg{}, data);
      const buffer dst{b.DBP, b.DBW, p};
      for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x)
          generic.write_pixel(dst, x0 + x, y0 + y, unpack(data, value_bits(p), y * w + x));
      ASSERT_TRUE(std::equal(fast.words(), fast.words() + memory_bytes / 4, generic.words()))
          << static_cast<int>(p) << " DBP " << b.DBP.value() << " DBW " << b.DBW.value() << " at " << x0 << ", " << y0
          << " size " << w << "x" << h;
    }
}

TEST(GsMemoryClut, Csm1LoadFromUploadedImageEqualsThePalette) {
  std::mt19937 rng(5);
  std::array<std::uint32_t, 256> palette{};
  for (auto& e : palette) e = rng();
  std::vector<std::uint8_t> image(16 * 16 * 4);
  for (std::uint32_t i = 0; i < 256; ++i) {
    const auto [x, y] = csm1_xy(i);
    for (unsigned k = 0; k < 4; ++k) image[(y * 16 + x) * 4 + k] = static_cast<std::uint8_t>(palette[i] >> (8 * k));
  }
  local_memory m;
  host_to_local(m, bitbltbuf_reg{u<14>(0), u<6>(0), psm::PSMCT32, u<14>(3000), u<6>(1), psm::PSMCT32}, trxpos_reg{},
                trxreg_reg{u<12>(16), u<12>(16)}, trxdir_reg{}, image);
  tex0_reg t;
  t.PSM = psm::PSMT8;
  t.CBP = u<14>(3000);
  t.CLD = u3::from_wrapped(1);
  const clut_state s = load_clut(m, t, clut_state{});
  for (std::uint32_t i = 0; i < 256; ++i) {
    ASSERT_EQ(s.buffer[i].to_u32(), palette[i]) << "entry " << i;
    ASSERT_EQ(clut_t8(s.buffer, u8::from_wrapped(i)).to_u32(), palette[i]);
  }
  // PSMT4: an 8×2 image in raster order, loaded at entry 16·CSA.
  std::vector<std::uint8_t> small(8 * 2 * 4);
  for (std::uint32_t i = 0; i < 16; ++i)
    for (unsigned k = 0; k < 4; ++k) small[i * 4 + k] = static_cast<std::uint8_t>(palette[200 + i] >> (8 * k));
  host_to_local(m, bitbltbuf_reg{u<14>(0), u<6>(0), psm::PSMCT32, u<14>(3004), u<6>(1), psm::PSMCT32}, trxpos_reg{},
                trxreg_reg{u<12>(8), u<12>(2)}, trxdir_reg{}, small);
  t.PSM = psm::PSMT4;
  t.CBP = u<14>(3004);
  t.CSA = fixed::u5::from_wrapped(3);
  const clut_state s4 = load_clut(m, t, s);
  for (std::uint32_t i = 0; i < 256; ++i)
    ASSERT_EQ(s4.buffer[i].to_u32(), i / 16 == 3 ? palette[200 + i % 16] : palette[i]) << "entry " << i;
}

TEST(GsMemoryClut, LoadControlTable) {
  local_memory m;
  m.write_pixel(buffer{u<14>(64), u<6>(1), psm::PSMCT32}, 0, 0, 0x11223344u);
  tex0_reg t;
  t.PSM = psm::PSMT8;
  t.CBP = u<14>(64);
  struct row {
    unsigned cld, cbp0_before, cbp1_before;
    bool loads;
    unsigned cbp0_after, cbp1_after;
  };
  const row rows[] = {{0, 0, 0, false, 0, 0},   {1, 0, 0, true, 0, 0},    {2, 0, 0, true, 64, 0},
                      {3, 0, 0, true, 0, 64},   {4, 64, 0, false, 64, 0}, {4, 5, 0, true, 64, 0},
                      {5, 0, 64, false, 0, 64}, {5, 0, 5, true, 0, 64}};
  for (const auto& r : rows) {
    t.CLD = u3::from_wrapped(r.cld);
    const clut_state s = load_clut(m, t, clut_state{{}, u<14>(r.cbp0_before), u<14>(r.cbp1_before)});
    EXPECT_EQ(s.buffer[0].to_u32() == 0x11223344u, r.loads) << "CLD " << r.cld;
    EXPECT_EQ(s.CBP0.value(), static_cast<int>(r.cbp0_after)) << "CLD " << r.cld;
    EXPECT_EQ(s.CBP1.value(), static_cast<int>(r.cbp1_after)) << "CLD " << r.cld;
  }
  t.CLD = u3::from_wrapped(6);
  EXPECT_THROW(load_clut(m, t, clut_state{}), register_error);
  t.CLD = u3::from_wrapped(2);
  t.PSM = psm::PSMCT32;  // not indexed: nothing loads and CBP0 stays
  EXPECT_EQ(load_clut(m, t, clut_state{}).CBP0.value(), 0);
}

// Every coordinate -2048..2047, every texture size, a sweep of MIN/MAX, against modular arithmetic
// and std::clamp.
TEST(GsMemoryWrap, FourModesAgainstAReference) {
  const std::uint32_t bounds[] = {0, 1, 3, 7, 8, 15, 31, 100, 512, 1023};
  for (unsigned tw = 0; tw <= 10; ++tw) {
    const std::int32_t n = 1 << tw;
    for (const std::uint32_t a : bounds)
      for (const std::uint32_t b : bounds)
        for (std::int32_t c = -2048; c < 2048; ++c) {
          const auto TW = fixed::u4::from_wrapped(tw);
          const std::int32_t lo = std::min<std::int32_t>(static_cast<std::int32_t>(a), n - 1);
          const std::int32_t hi = std::min<std::int32_t>(static_cast<std::int32_t>(b), n - 1);
          ASSERT_EQ(wrap_texel(wrap_mode::REPEAT, c, TW, u<10>(a), u<10>(b)),
                    static_cast<std::uint32_t>(((c % n) + n) % n));
          ASSERT_EQ(wrap_texel(wrap_mode::CLAMP, c, TW, u<10>(a), u<10>(b)),
                    static_cast<std::uint32_t>(std::clamp(c, 0, n - 1)));
          if (lo <= hi) {
            ASSERT_EQ(wrap_texel(wrap_mode::REGION_CLAMP, c, TW, u<10>(a), u<10>(b)),
                      static_cast<std::uint32_t>(std::clamp(c, lo, hi)));
          }
          // REGION_REPEAT: the low bits set in MSK come from the coordinate, FIX supplies the rest:
          // bit k of the result = MSK_k ? coord_k : 0, OR FIX_k (bits below the texture size only).
          std::uint32_t expect = 0;
          for (unsigned k = 0; k < tw; ++k) {
            const bool from_coord = ((a >> k) & 1u) && ((static_cast<std::uint32_t>(c) >> k) & 1u);
            if (from_coord || ((b >> k) & 1u)) expect |= 1u << k;
          }
          ASSERT_EQ(wrap_texel(wrap_mode::REGION_REPEAT, c, TW, u<10>(a), u<10>(b)), expect);
        }
  }
  const clamp_reg c{wrap_mode::REGION_REPEAT, wrap_mode::CLAMP, u<10>(7), u<10>(16), u<10>(0), u<10>(0)};
  EXPECT_EQ(wrap(c, fixed::u4::from_wrapped(8), fixed::u4::from_wrapped(4), 43, 99), (texel_coord{16 | 3, 15}));
}

}  // namespace
}  // namespace gs::mem

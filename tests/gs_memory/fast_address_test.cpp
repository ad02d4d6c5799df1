// The renderer's tabulated addresses (gs_memory/fast_address.hpp) against the address function they
// are built from, on every coordinate they claim: row + column for the 32- and 16-bit layouts over
// a sweep of widths and base pointers (and a whole 2048-row buffer as wide as the renderer's
// 512-pixel frames), the counterexample that PSMT8/PSMT4 are not sums, and the texel tables'
// addresses and reads against locate / read_pixel for every texel of the textures the methods use;
// local_memory's word-wise read / write against the byte-by-byte little-endian reading.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "formats.hpp"
#include "gs_memory/address.hpp"
#include "gs_memory/fast_address.hpp"
#include "gs_memory/local_memory.hpp"
#include "gs_memory/swizzle_tables.hpp"

namespace gs::mem {
namespace {

constexpr layout sum_layouts[] = {layout::ct32, layout::z32, layout::ct16, layout::ct16s, layout::z16, layout::z16s};
constexpr std::uint32_t base_pointers[] = {0, 1, 31, 32, 1000, 16351, 16383};  // page-aligned, not, wrapping

std::uint64_t expect_row_column(layout l, std::uint32_t bp, std::uint32_t bw, std::uint32_t w, std::uint32_t h) {
  const row_column_address a(l, bp, bw, w, h);
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x = 0; x < w; ++x)
      if (a.unit(x, y) != tables::unit_address(l, bp, bw, x, y)) {
        ADD_FAILURE() << test::name(l) << " BP " << bp << " BW " << bw << " (" << x << ", " << y << "): row + column 0x"
                      << std::hex << a.unit(x, y) << ", unit_address 0x" << tables::unit_address(l, bp, bw, x, y);
        return 0;
      }
  return std::uint64_t{w} * h;
}

TEST(FastAddress, RowPlusColumnIsTheAddressForEvery32And16BitLayout) {
  std::uint64_t checked = 0;
  for (const layout l : sum_layouts) {
    for (const std::uint32_t bw : {1u, 2u, 3u, 5u, 8u, 10u, 16u, 63u})
      for (const std::uint32_t bp : base_pointers)
        checked += expect_row_column(l, bp, bw, 64 * bw, 2 * page_size(l).h + 3);
    for (const std::uint32_t bp : {0u, 16383u}) checked += expect_row_column(l, bp, 8, 512, 2048);
  }
  std::printf("checked %llu (layout, BW, BP, x, y) coordinates\n", static_cast<unsigned long long>(checked));
}

// The sum property fails for the 8- and 4-bit layouts: counted over one page (PSMT8 texel (4, 2) is
// byte 1 of its block, texel (4, 0) byte 32 and (0, 2) byte 33: the "x ^ 4" of column 1).
TEST(FastAddress, Psmt8AndPsmt4AreNotRowPlusColumn) {
  EXPECT_EQ(tables::unit_address(layout::t8, 0, 2, 4, 2), 1u);
  EXPECT_EQ(tables::unit_address(layout::t8, 0, 2, 4, 0) + tables::unit_address(layout::t8, 0, 2, 0, 2), 65u);
  for (const layout l : {layout::t8, layout::t4}) {
    EXPECT_THROW(row_column_address(l, 0, 2, 128, 64), std::invalid_argument);
    const extent pg = page_size(l);
    const std::uint32_t bw = pg.w / 64;
    int not_sums = 0;
    for (std::uint32_t y = 0; y < pg.h; ++y)
      for (std::uint32_t x = 0; x < pg.w; ++x)
        not_sums += tables::unit_address(l, 0, bw, x, y) !=
                    tables::unit_address(l, 0, bw, x, 0) + tables::unit_address(l, 0, bw, 0, y);
    EXPECT_GT(not_sums, 0) << test::name(l);
  }
}

TEST(FastAddress, TexelTablesAreLocateAndReadPixelForEveryTexel) {
  local_memory m;
  std::mt19937 rng(14);
  for (std::uint32_t i = 0; i < memory_bytes / 4; ++i) m.words()[i] = static_cast<std::uint32_t>(rng());
  struct texture {
    psm p;
    std::uint32_t bw, w, h;
  };
  // The channel fetch's PSMT8 page (TBW = 2·FBW), a 256² normal map, its PSMT8H view, a 4-bit 256²
  // normal map and a 128×256 one at TBW 6 (PSMT4), the sphere map and a diffuse texture (PSMCT32), a
  // PSMZ32 view.
  const texture textures[] = {{psm::PSMT8, 16, 128, 64},   {psm::PSMT8, 4, 256, 256}, {psm::PSMT8H, 8, 512, 64},
                              {psm::PSMT4, 4, 256, 256},   {psm::PSMT4, 6, 128, 256}, {psm::PSMCT32, 1, 64, 64},
                              {psm::PSMCT32, 4, 256, 128}, {psm::PSMZ32, 8, 512, 64}};
  std::uint64_t checked = 0;
  for (const texture& t : textures) {
    const texel_addresses a(t.p, t.bw, t.w, t.h);
    for (const std::uint32_t bp : base_pointers) {
      const buffer b{fixed::uint<14>::from_wrapped(bp), fixed::uint<6>::from_wrapped(t.bw), t.p};
      for (std::uint32_t v = 0; v < t.h; ++v)
        for (std::uint32_t u = 0; u < t.w; ++u) {
          ASSERT_EQ(a.byte(u, v, bp), locate(b, u, v).byte)
              << "PSM " << static_cast<int>(t.p) << " BP " << bp << " (" << u << ", " << v << ")";
          ASSERT_EQ(a.read(m, u, v, bp), m.read_pixel(b, u, v))
              << "PSM " << static_cast<int>(t.p) << " BP " << bp << " (" << u << ", " << v << ")";
          ++checked;
        }
    }
  }
  EXPECT_THROW(texel_addresses(psm::PSMT4HL, 2, 128, 128), std::invalid_argument);
  EXPECT_THROW(texel_addresses(psm::PSMCT16, 1, 64, 64), std::invalid_argument);
  std::printf("checked %llu (texture, BP, u, v) texels\n", static_cast<unsigned long long>(checked));
}

// The byte-by-byte reference: the value's bits little-endian from at.byte, starting at bit at.bit.
std::uint32_t read_bytes(const local_memory& m, const location& at) {
  std::uint64_t v = 0;
  for (unsigned i = 0; i < (at.bit + at.bits + 7) / 8; ++i) v |= std::uint64_t{m.byte(at.byte + i)} << (8 * i);
  return static_cast<std::uint32_t>((v >> at.bit) & ((std::uint64_t{1} << at.bits) - 1));
}

// Every location of two pages (BP 32, BW 2 and 4) of every format: the location lies in one word,
// read = the byte-wise reading of random memory, and write sets exactly those bits (the other bytes
// and bits of the memory are as before, read back byte by byte).
TEST(FastAddress, WordWiseReadAndWriteAreTheByteWiseReading) {
  local_memory m;
  std::mt19937 rng(3);
  for (std::uint32_t i = 0; i < memory_bytes / 4; ++i) m.words()[i] = static_cast<std::uint32_t>(rng());
  std::uint64_t checked = 0;
  for (const psm p : test::all_psms) {
    const extent pg = page_size(layout_of(p));
    const buffer b{fixed::uint<14>::literal(32), fixed::uint<6>::from_wrapped(pg.w / 32), p};
    for (std::uint32_t y = 0; y < pg.h; ++y)
      for (std::uint32_t x = 0; x < 2 * pg.w; ++x) {
        const location at = locate(b, x, y);
        ASSERT_LE(8 * (at.byte % 4) + at.bit + at.bits, 32u)
            << "PSM " << static_cast<int>(p) << " (" << x << ", " << y << ")";
        ASSERT_EQ(m.read(at), read_bytes(m, at)) << "PSM " << static_cast<int>(p) << " (" << x << ", " << y << ")";
        const std::uint32_t word = at.byte / 4, before = m.words()[word], v = static_cast<std::uint32_t>(rng());
        m.write(at, v);
        const std::uint64_t mask = ((std::uint64_t{1} << at.bits) - 1) << (8 * (at.byte % 4) + at.bit);
        ASSERT_EQ(read_bytes(m, at), v & ((std::uint64_t{1} << at.bits) - 1));
        ASSERT_EQ(m.words()[word] & ~mask, before & ~mask)
            << "PSM " << static_cast<int>(p) << " (" << x << ", " << y << ")";
        ++checked;
      }
  }
  std::printf("checked %llu (format, x, y) locations\n", static_cast<unsigned long long>(checked));
}

}  // namespace
}  // namespace gs::mem

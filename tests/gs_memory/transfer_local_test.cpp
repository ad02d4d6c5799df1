// Local -> host and local -> local transfers against direct construction: pixels placed with
// write_pixel and read back by hand-unpacking the host bytes; copies checked pixel by pixel against
// the source values, every other nibble of memory unchanged; TRXPOS.DIR's four orders on an
// overlapping copy against memmove-style and smearing results worked out by hand.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "formats.hpp"
#include "gs_memory/transfer.hpp"

namespace gs::mem {
namespace {

template <int N>
fixed::uint<N> u(std::uint32_t v) {
  return fixed::uint<N>::from_wrapped(v);
}
std::uint32_t value_mask(psm p) { return value_bits(p) == 32 ? 0xFFFFFFFFu : (1u << value_bits(p)) - 1; }

using test::unpack;

TEST(GsMemoryTransfer, LocalToHostReturnsThePixelsPacked) {
  std::mt19937 rng(21);
  for (const psm p : test::all_psms) {
    local_memory m;
    const buffer src{u<14>(96), u<6>(2), p};
    std::vector<std::uint32_t> values(19 * 7);
    for (std::uint32_t y = 0; y < 7; ++y)
      for (std::uint32_t x = 0; x < 19; ++x) {
        values[y * 19 + x] = rng() & value_mask(p);
        m.write_pixel(src, 11 + x, 3 + y, values[y * 19 + x]);
      }
    const bitbltbuf_reg b{u<14>(96), u<6>(2), p, u<14>(0), u<6>(0), psm::PSMCT32};
    const trxpos_reg pos{u<11>(11), u<11>(3), u<11>(0), u<11>(0), u<2>(0)};
    const std::vector<std::uint8_t> data = local_to_host(m, b, pos, {u<12>(19), u<12>(7)}, {xdir::local_to_host});
    ASSERT_EQ(data.size(), transfer_bytes(p, 19, 7));
    for (std::size_t i = 0; i < values.size(); ++i)
      ASSERT_EQ(unpack(data, value_bits(p), i), values[i]) << static_cast<int>(p) << " pixel " << i;
    // Host -> local of those bytes elsewhere and back gives the same bytes.
    host_to_local(m, {u<14>(0), u<6>(0), psm::PSMCT32, u<14>(2048), u<6>(2), p},
                  {u<11>(0), u<11>(0), u<11>(5), u<11>(1), u<2>(0)}, {u<12>(19), u<12>(7)}, {}, data);
    EXPECT_EQ(
        local_to_host(m, {u<14>(2048), u<6>(2), p, u<14>(0), u<6>(0), psm::PSMCT32},
                      {u<11>(5), u<11>(1), u<11>(0), u<11>(0), u<2>(0)}, {u<12>(19), u<12>(7)}, {xdir::local_to_host}),
        data);
    EXPECT_THROW(local_to_host(m, b, pos, {u<12>(19), u<12>(7)}, {xdir::host_to_local}), std::invalid_argument);
  }
}

TEST(GsMemoryTransfer, LocalToLocalCopiesEveryPairOfEqualSizedFormats) {
  std::mt19937 rng(22);
  int pairs = 0;
  for (const psm sp : test::all_psms)
    for (const psm dp : test::all_psms) {
      if (value_bits(sp) != value_bits(dp)) continue;
      ++pairs;
      local_memory m;
      for (std::uint32_t a = 0; a < 256 * 1024; ++a) m.set_byte(a, static_cast<std::uint8_t>(rng()));
      const buffer src{u<14>(64), u<6>(3), sp}, dst{u<14>(512), u<6>(2), dp};
      std::vector<std::uint32_t> expect(21 * 9);
      for (std::uint32_t y = 0; y < 9; ++y)
        for (std::uint32_t x = 0; x < 21; ++x) expect[y * 21 + x] = m.read_pixel(src, 40 + x, 17 + y);
      const local_memory before = m;
      const bitbltbuf_reg b{u<14>(64), u<6>(3), sp, u<14>(512), u<6>(2), dp};
      local_to_local(m, b, {u<11>(40), u<11>(17), u<11>(70), u<11>(2), u<2>(0)}, {u<12>(21), u<12>(9)},
                     {xdir::local_to_local});
      std::vector<bool> written(256 * 1024 * 2, false);  // nibbles
      for (std::uint32_t y = 0; y < 9; ++y)
        for (std::uint32_t x = 0; x < 21; ++x) {
          ASSERT_EQ(m.read_pixel(dst, 70 + x, 2 + y), expect[y * 21 + x])
              << static_cast<int>(sp) << " -> " << static_cast<int>(dp);
          const location at = locate(dst, 70 + x, 2 + y);
          for (unsigned n = 0; n < at.bits / 4; ++n) written[(at.byte * 8 + at.bit) / 4 + n] = true;
        }
      for (std::uint32_t n = 0; n < written.size(); ++n)
        if (!written[n]) {
          ASSERT_EQ((m.byte(n / 2) >> (4 * (n % 2))) & 0xF, (before.byte(n / 2) >> (4 * (n % 2))) & 0xF);
        }
    }
  EXPECT_EQ(pairs, 2 * 2 + 2 * 2 + 4 * 4 + 2 * 2 + 3 * 3);  // 32-, 24-, 16-, 8-, 4-bit families
}

// A row of 8 PSMCT32 pixels v0..v7 copied onto itself one pixel to the right (7 wide), and a column
// one pixel down: from the far end (DIRX / DIRY set) it moves like memmove, from the near end every
// copied pixel reads the one just written (a smear of v0).
TEST(GsMemoryTransfer, DirOrdersAnOverlappingCopy) {
  for (unsigned dir = 0; dir < 4; ++dir)
    for (const bool vertical : {false, true}) {
      local_memory m;
      const buffer b{u<14>(0), u<6>(1), psm::PSMCT32};
      for (std::uint32_t i = 0; i < 8; ++i) m.write_pixel(b, vertical ? 0 : i, vertical ? i : 0, 100 + i);
      const bitbltbuf_reg blt{u<14>(0), u<6>(1), psm::PSMCT32, u<14>(0), u<6>(1), psm::PSMCT32};
      const trxpos_reg pos{u<11>(0), u<11>(0), u<11>(vertical ? 0 : 1), u<11>(vertical ? 1 : 0), u<2>(dir)};
      local_to_local(m, blt, pos, {u<12>(vertical ? 1 : 7), u<12>(vertical ? 7 : 1)}, {xdir::local_to_local});
      const bool far_end = vertical ? (dir & 1) != 0 : (dir & 2) != 0;
      for (std::uint32_t i = 0; i < 8; ++i) {
        const std::uint32_t expect = i == 0 ? 100 : far_end ? 100 + i - 1 : 100;
        ASSERT_EQ(m.read_pixel(b, vertical ? 0 : i, vertical ? i : 0), expect)
            << "DIR " << dir << (vertical ? " column" : " row") << " pixel " << i;
      }
    }
}

TEST(GsMemoryTransfer, LocalToLocalWrapsAt2048AndRejectsWhatIsNotModelled) {
  local_memory m;
  const buffer src{u<14>(0), u<6>(32), psm::PSMCT32}, dst{u<14>(8192), u<6>(1), psm::PSMCT32};
  for (std::uint32_t x : {2046u, 2047u, 0u, 1u}) m.write_pixel(src, x, 5, 0xC0DE0000u + x);
  const bitbltbuf_reg b{u<14>(0), u<6>(32), psm::PSMCT32, u<14>(8192), u<6>(1), psm::PSMCT32};
  local_to_local(m, b, {u<11>(2046), u<11>(5), u<11>(0), u<11>(0), u<2>(0)}, {u<12>(4), u<12>(1)},
                 {xdir::local_to_local});
  const std::uint32_t xs[] = {2046u, 2047u, 0u, 1u};
  for (std::uint32_t i = 0; i < 4; ++i) EXPECT_EQ(m.read_pixel(dst, i, 0), 0xC0DE0000u + xs[i]);
  EXPECT_THROW(local_to_local(m, {u<14>(0), u<6>(1), psm::PSMCT32, u<14>(64), u<6>(1), psm::PSMCT16}, {},
                              {u<12>(1), u<12>(1)}, {xdir::local_to_local}),
               std::invalid_argument);
  EXPECT_THROW(local_to_local(m, b, {}, {u<12>(1), u<12>(1)}, {xdir::host_to_local}), std::invalid_argument);
}

}  // namespace
}  // namespace gs::mem

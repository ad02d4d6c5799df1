// Exhaustive checks of the GS local-memory layout across page boundaries: the two formulations agree
// on every pixel of buffers of every width 1..63 at a sweep of base pointers, and a buffer the size of
// the whole memory is a bijection onto it.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <vector>

#include "formats.hpp"
#include "gs_memory/swizzle_bits.hpp"
#include "gs_memory/swizzle_tables.hpp"

namespace gs::mem {
namespace {

TEST(GsMemoryExhaustive, FormulationsAgreeForEveryWidthAndASweepOfBasePointers) {
  const std::uint32_t bps[] = {0, 1, 31, 32, 1000, 16351, 16383};  // page-aligned, not, and wrapping
  std::uint64_t checked = 0;
  for (const layout l : test::all_layouts) {
    const extent pg = page_size(l);
    for (std::uint32_t bw = 1; bw < 64; ++bw)
      for (const std::uint32_t bp : bps) {
        const std::uint32_t w = bw * 64 < pg.w ? pg.w : bw * 64;
        for (std::uint32_t y = 0; y < 2 * pg.h + 3; ++y)
          for (std::uint32_t x = 0; x < w; ++x) {
            const std::uint32_t a = tables::unit_address(l, bp, bw, x, y);
            if (a != bits::unit_address(l, bp, bw, x, y))
              FAIL() << test::name(l) << " BP " << bp << " BW " << bw << " (" << x << ", " << y << "): tables 0x"
                     << std::hex << a << " bits 0x" << bits::unit_address(l, bp, bw, x, y);
            ++checked;
          }
      }
  }
  std::printf("checked %llu (layout, BW 1..63, BP, x, y) coordinates\n", static_cast<unsigned long long>(checked));
}

// A buffer exactly the size of local memory (BW chosen so it is page-aligned) hits every unit once.
TEST(GsMemoryExhaustive, AWholeMemoryBufferIsABijection) {
  for (const layout l : test::all_layouts) {
    const std::uint32_t units = memory_bytes * 8 / unit_bits(l);
    const std::uint32_t bw = unit_bits(l) >= 16 ? 16 : 32;
    const std::uint32_t w = bw * 64, h = units / w;
    std::vector<std::uint8_t> hit(units, 0);
    for (std::uint32_t y = 0; y < h; ++y)
      for (std::uint32_t x = 0; x < w; ++x) {
        const std::uint32_t a = tables::unit_address(l, 0, bw, x, y);
        ASSERT_LT(a, units);
        ASSERT_EQ(hit[a], 0) << test::name(l) << " (" << x << ", " << y << ") hits unit " << a << " twice";
        hit[a] = 1;
      }
  }
}

}  // namespace
}  // namespace gs::mem

// gs::depth_test against the emulators' formulations written another way: PCSX2 GSDrawScanline's
// TestZ masks the stored word by shifting (<< 8 >> 8 for Z24, << 16 >> 16 for Z16) and fails
// GEQUAL where zs < zd; DobieStation's depth_test clamps with min(). Both are re-expressed here as
// shifts and 64-bit arithmetic (not the unit's mask-and-min), swept over the edge values of every
// width and every TEST/ZBUF setting.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "gs_arith/depth_test.hpp"

namespace {

using gs::depth_test;
using gs::test_reg;
using gs::zbuf_psm;
using gs::zbuf_reg;
using gs::ztst;

// The stored bits by shifting the word left and back (PCSX2's way).
std::uint32_t stored_by_shift(zbuf_psm p, std::uint32_t zd) {
  switch (p) {
    case zbuf_psm::PSMZ24: return (zd << 8) >> 8;
    case zbuf_psm::PSMZ16:
    case zbuf_psm::PSMZ16S: return (zd << 16) >> 16;
    default: return zd;
  }
}
// The source clamp in 64-bit arithmetic: the largest value of the format is 2^bits − 1.
std::uint32_t clamped(zbuf_psm p, std::uint32_t z) {
  const int bits = p == zbuf_psm::PSMZ32 ? 32 : p == zbuf_psm::PSMZ24 ? 24 : 16;
  const std::uint64_t top = (std::uint64_t{1} << bits) - 1;
  return static_cast<std::uint32_t>(std::uint64_t{z} > top ? top : z);
}

TEST(DepthTest, EveryTestAndFormatOnTheEdgeValues) {
  const std::vector<std::uint32_t> values = {
      0u,         1u,         0x7FFFu,     0xFFFFu,     0x10000u,    0x10001u,    0x808080u,   0xFFFFFEu,  0xFFFFFFu,
      0x1000000u, 0x1000001u, 0x7FFFFFFFu, 0x80000000u, 0xFF000000u, 0xFFFFFFFEu, 0xFFFFFFFFu, 0xAB123456u};
  long checked = 0;
  for (const zbuf_psm p : {zbuf_psm::PSMZ32, zbuf_psm::PSMZ24, zbuf_psm::PSMZ16, zbuf_psm::PSMZ16S})
    for (const bool zte : {false, true})
      for (const ztst t : {ztst::NEVER, ztst::ALWAYS, ztst::GEQUAL, ztst::GREATER})
        for (const bool zmsk : {false, true})
          for (const std::uint32_t z : values)
            for (const std::uint32_t zd : values) {
              test_reg test;
              test.ZTE = zte;
              test.ZTST = t;
              const zbuf_reg zbuf{{}, p, zmsk};
              const std::uint32_t zs = clamped(p, z), old = stored_by_shift(p, zd);
              bool fails = false;  // PCSX2's "test |=" conditions
              if (zte && t == ztst::NEVER) fails = true;
              if (zte && t == ztst::GEQUAL) fails = zs < old;
              if (zte && t == ztst::GREATER) fails = zs <= old;
              const gs::depth_result r = depth_test(test, zbuf, z, zd);
              ASSERT_EQ(r.pass, !fails) << "z " << z << " zd " << zd;
              ASSERT_EQ(r.write_z, !fails && !zmsk);
              ASSERT_EQ(r.z, zs);
              ++checked;
            }
  EXPECT_EQ(checked, 4L * 2 * 4 * 2 * 17 * 17);
}

TEST(DepthTest, KnownCases) {
  test_reg gequal;
  gequal.ZTE = true;
  gequal.ZTST = ztst::GEQUAL;
  // PSMZ24: the top byte of the stored word is not part of the depth (0xFF000000 reads as 0).
  EXPECT_TRUE(depth_test(gequal, {{}, zbuf_psm::PSMZ24, false}, 0, 0xFF000000u).pass);
  EXPECT_FALSE(depth_test(gequal, {{}, zbuf_psm::PSMZ32, false}, 0, 0xFF000000u).pass);
  // A source Z above the format's range is clamped before the compare and the write.
  const gs::depth_result r = depth_test(gequal, {{}, zbuf_psm::PSMZ16, false}, 0x12345u, 0xFFFFu);
  EXPECT_TRUE(r.pass);
  EXPECT_EQ(r.z, 0xFFFFu);
  // Equal depths pass GEQUAL and fail GREATER.
  test_reg greater = gequal;
  greater.ZTST = ztst::GREATER;
  EXPECT_TRUE(depth_test(gequal, {{}, zbuf_psm::PSMZ24, true}, 0x808080u, 0x808080u).pass);
  EXPECT_FALSE(depth_test(greater, {{}, zbuf_psm::PSMZ24, true}, 0x808080u, 0x808080u).pass);
  // ZMSK = 1: the pixel passes, Z is not written.
  EXPECT_FALSE(depth_test(gequal, {{}, zbuf_psm::PSMZ24, true}, 5, 4).write_z);
}

}  // namespace

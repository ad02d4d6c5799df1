// gs_arith/depth_test.hpp — TEST.ZTE / ZTST with ZBUF.PSM / ZMSK: whether a pixel passes the depth test
// and what it leaves in the Z buffer.
//
// GS User's Manual (TEST_1, ZBUF_1): ZTST 0 NEVER, 1 ALWAYS, 2 GEQUAL, 3 GREATER (larger Z is nearer);
//   ZBUF_1  ZBP:9 _:15 PSM:4 _:4 ZMSK:1   PSM 0 PSMZ32, 1 PSMZ24, 2 PSMZ16, 10 PSMZ16S (the Z formats'
//   codes 0x30.. without bits 4-5); ZMSK = 1: the Z buffer is not written.
// Evidence, read with the search tool:
// - PCSX2 `pcsx2/GS/Renderers/SW/GSDrawScanline.cpp` `GSDrawScanline::CDrawScanline`, block "TestZ":
//   the source Z is clamped to the format (min with 0xFFFFFFFF >> 8·zpsm), the stored Z is read with the
//   format's bits only (<< 8 >> 8 for Z24, << 16 >> 16 for Z16), the comparison is unsigned; GEQUAL
//   fails where zs < zd, GREATER where zs <= zd; the write is masked by ZMSK (`zm`).
// - DobieStation `src/core/gsthread.cpp` `GraphicsSynthesizerThread::depth_test`: NEVER fails, ALWAYS
//   passes, GEQUAL z >= zd, GREATER z > zd, with z = min(z, 0xFFFFFF) for PSMZ24 and min(z, 0xFFFF)
//   for PSMZ16/16S; its `draw_pixel` tests only when TEST.ZTE is set.
// Confidence: high for ZTST, the clamp and the widths (two emulators and the manual agree). ZTE = 0:
// modelled as "no test, every pixel passes" (DobieStation); the manual forbids ZTE = 0 in a drawing,
// so no game depends on it (medium).
#pragma once

#include <algorithm>
#include <cstdint>

#include "fixed/integer.hpp"
#include "gs_arith/alpha_test.hpp"

namespace gs {

// ZBUF_1.PSM (4 bits).
enum class zbuf_psm : std::uint8_t { PSMZ32 = 0x0, PSMZ24 = 0x1, PSMZ16 = 0x2, PSMZ16S = 0xA };

struct zbuf_reg {
  fixed::uint<9> ZBP{};  // 8 KiB pages
  zbuf_psm PSM = zbuf_psm::PSMZ32;
  bool ZMSK = false;
  friend constexpr bool operator==(const zbuf_reg&, const zbuf_reg&) = default;
};

// The bits of a depth value the Z format stores.
constexpr unsigned z_bits(zbuf_psm p) noexcept {
  switch (p) {
    case zbuf_psm::PSMZ32: return 32;
    case zbuf_psm::PSMZ24: return 24;
    case zbuf_psm::PSMZ16:
    case zbuf_psm::PSMZ16S: return 16;
  }
  return 32;
}

struct depth_result {
  bool pass;        // the pixel goes on to the frame write
  bool write_z;     // the Z buffer takes `z`
  std::uint32_t z;  // the stored value: the source Z clamped to the format's bits
  friend constexpr bool operator==(const depth_result&, const depth_result&) = default;
};

// The depth test of one pixel with source depth z (32-bit, from XYZ2/the Z plane) against the
// stored word zd (the Z buffer's location; bits above the format's width are ignored).
constexpr depth_result depth_test(const test_reg& test, const zbuf_reg& zbuf, std::uint32_t z,
                                  std::uint32_t zd) noexcept {
  const unsigned bits = z_bits(zbuf.PSM);
  const std::uint32_t max = bits == 32 ? 0xFFFFFFFFu : (std::uint32_t{1} << bits) - 1;
  const std::uint32_t zs = std::min(z, max);
  const std::uint32_t stored = zd & max;
  bool pass = true;
  if (test.ZTE) {
    switch (test.ZTST) {
      case ztst::NEVER: pass = false; break;
      case ztst::ALWAYS: pass = true; break;
      case ztst::GEQUAL: pass = zs >= stored; break;
      case ztst::GREATER: pass = zs > stored; break;
    }
  }
  return {pass, pass && !zbuf.ZMSK, zs};
}

}  // namespace gs

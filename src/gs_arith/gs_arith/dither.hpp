// gs_arith/dither.hpp — DTHE / DIMX: a 4×4 matrix of 3-bit offsets added to the blended colour.
//
// Evidence (../shared/spec/gs-alu-facts.md, "After the blend", step 1; matrix rows dither_decode, dither_targets of
// docs/evidence.md): the offset DIMX[y & 3][x & 3] is added to each RGB channel of the wide (s11)
// blend output, before COLCLAMP clamp/wrap (PCSX2 GSDrawScanline.cpp CDrawScanline "WriteFrame";
// DobieStation gsthread.cpp draw_pixel). No hardware recording covers dithering, so these are options:
// - dither_decode: twos_complement −4..+3 (default; PCSX2 GSRegs.h `s32 DM00:3`, expanded by
//   GSState::ExpandDIMX) | sign_magnitude −3..+3 (DobieStation draw_pixel at 3a23544b: `dither & 0x4`
//   subtracts `dither & 0x3`) | inverted_magnitude −1..−4 for 4..7 (DobieStation at 68dd073e, issue 17).
//   Plausibility: the DIMX commonly set by PS2 programs (forums.ps2dev.org, "HOWTO: Make 16bit mode look
//   like 32bit", rows 4,2,5,3 / 0,6,1,7 / 5,3,4,2 / 1,7,0,6) reads exactly as the (transposed) 4×4 Bayer
//   matrix of offsets −4..+3 under twos_complement; inverted_magnitude gives the same offsets with the
//   four negative levels in reverse order; sign_magnitude never gives −4 and gives 0 four times.
// - dither_targets: sixteen_bit_only (default; PCSX2 SW `fpsm == 2`, HW `dfmt == 2`) | all_formats
//   (DobieStation draw_pixel, no format test).
// DIMX layout (GS manual): DMij occupies bits 16·i + 4·j .. +2 (row i = y & 3, column j = x & 3).
#pragma once

#include <array>
#include <cstdint>

#include "fixed/integer.hpp"
#include "gs_arith/colour.hpp"
#include "gs_arith/frame_write.hpp"
#include "gs_arith/options.hpp"

namespace gs {

using fixed::s3;
using fixed::u3;

struct dimx_reg {
  std::array<std::array<u3, 4>, 4> DM{};  // DM[i][j]: row i = y & 3, column j = x & 3
  friend constexpr bool operator==(const dimx_reg&, const dimx_reg&) = default;
};

// One 3-bit DIMX entry as a signed offset.
constexpr s3 dither_value(u3 dm, dither_decode decode) noexcept {
  const int bits = dm.value();
  switch (decode) {
    case dither_decode::twos_complement: return s3::from_wrapped(bits);  // 4..7 -> −4..−1
    case dither_decode::sign_magnitude: {
      const int magnitude = bits & 3;
      return s3::from_wrapped((bits & 4) != 0 ? -magnitude : magnitude);  // 4 is −0
    }
    case dither_decode::inverted_magnitude: {
      const int magnitude = bits & 3;
      return s3::from_wrapped((bits & 4) != 0 ? -(magnitude + 1) : magnitude);  // 4..7 -> −1..−4
    }
  }
  return s3{};
}

constexpr bool dither_applies(bool DTHE, frame_psm psm, const model_options& o) noexcept {
  return DTHE && (o.dither_on == dither_targets::all_formats || bits_of(psm) == pixel_bits::b16);
}

// The blend output plus the pixel's dither offset. Blend outputs lie in −509..763, so the sum lies
// in −513..766 and fits s11 exactly (the saturating narrow never changes such a value).
constexpr rgb_wide dither(rgb_wide v, const dimx_reg& dimx, unsigned x, unsigned y, bool DTHE, frame_psm psm,
                          const model_options& o) noexcept {
  if (!dither_applies(DTHE, psm, o)) return v;
  const s3 d = dither_value(dimx.DM[y & 3][x & 3], o.dither);
  auto add = [&](s11 c) { return (c + d).narrow<11, fixed::signedness::is_signed, fixed::overflow::saturate>(); };
  return {add(v.r), add(v.g), add(v.b)};
}

}  // namespace gs

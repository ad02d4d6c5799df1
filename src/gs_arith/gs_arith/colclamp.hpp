// gs_arith/colclamp.hpp — COLCLAMP.CLAMP: the blended colour back to 8 bits.
//
// CLAMP = 1 clamps each channel to 0..255 (HW-confirmed through the blend recordings).
// CLAMP = 0 keeps the low 8 bits (wrap, mod 256): no HW recording covers it; the paper (section 3.3,
// footnote) computes "modulo by 256 on the GS with color clamping disabled", and PCSX2 SW
// (GSDrawScanline.cpp CDrawScanline "WriteFrame"), the PCSX2 HW shaders (tfx_ps_post.inc
// ps_color_clamp_wrap), DobieStation (gsthread.cpp draw_pixel) and Play! (GSH_VulkanDrawDesktop.cpp)
// all keep the low 8 bits (matrix row A1 of docs/evidence.md; confidence: medium, no hardware test).
#pragma once

#include "fixed/integer.hpp"
#include "gs_arith/colour.hpp"

namespace gs {

constexpr u8 colclamp_channel(s11 v, bool clamp) noexcept {
  return clamp ? v.narrow<8, fixed::signedness::is_unsigned, fixed::overflow::saturate>()
               : v.narrow<8, fixed::signedness::is_unsigned, fixed::overflow::wrap>();
}

// RGB through COLCLAMP; alpha (As) is passed in unchanged.
constexpr rgba8 colclamp(rgb_wide v, u8 alpha, bool clamp) noexcept {
  return {colclamp_channel(v.r, clamp), colclamp_channel(v.g, clamp), colclamp_channel(v.b, clamp), alpha};
}

}  // namespace gs

// gs_arith/bilinear.hpp — texel footprint and filtering (TEX1.MMAG/MMIN = LINEAR, or NEAREST).
//
// Evidence (../shared/spec/gs-alu-facts.md, "Rasterisation and interpolation"; matrix row bilinear of
// docs/evidence.md): PCSX2 SW (GSDrawScanline.cpp CDrawScanline, `lerp16_4`): subtract half a texel,
// keep 4 fraction bits as the weight, c = c0 + (((c1 − c0)·w) >> 4) with an arithmetic (floor) shift, horizontally then
// vertically, on all four channels. DobieStation (gsthread.cpp tex_lookup) takes the same footprint and
// 4-bit weights but sums the four texels at once, Σ (w/16)·(w'/16)·c in doubles (exact: every term is a
// multiple of 1/256 below 2^16), truncated on the store: floor(Σ w·c / 256). Play! (Vulkan
// CDrawDesktop) does that sum in float with unquantised weights. No hardware recording: model option
// `bilinear` = lerp16_4 (default) | nearest (filtering off) | weighted_sum_4 (the one-step sum).
// Coordinates are texel coordinates in 12.4 fixed point (UV with FST = 1, or s/q·2^TW converted).
#pragma once

#include <cstdint>

#include "fixed/integer.hpp"
#include "fixed/rounding.hpp"
#include "gs_arith/colour.hpp"
#include "gs_arith/options.hpp"

namespace gs {

using fixed::u4;

// The texels (u0, v0) .. (u0 + 1, v0 + 1) and the weights of the second column and row (0..15).
// Nearest sampling is the footprint with both weights 0: the filter then returns texel (u0, v0).
struct texel_footprint {
  std::int32_t u0, v0;
  u4 wu, wv;
  friend constexpr bool operator==(const texel_footprint&, const texel_footprint&) = default;
};

constexpr texel_footprint footprint(std::int32_t u16, std::int32_t v16, bilinear_mode mode) noexcept {
  switch (mode) {
    case bilinear_mode::lerp16_4:
    case bilinear_mode::weighted_sum_4: {
      const std::int64_t u = std::int64_t{u16} - 8, v = std::int64_t{v16} - 8;  // minus half a texel
      return {static_cast<std::int32_t>(fixed::shift_right<fixed::rounding::floor>(u, 4)),
              static_cast<std::int32_t>(fixed::shift_right<fixed::rounding::floor>(v, 4)), u4::from_wrapped(u),
              u4::from_wrapped(v)};
    }
    case bilinear_mode::nearest:
      return {fixed::shift_right<fixed::rounding::floor>(u16, 4), fixed::shift_right<fixed::rounding::floor>(v16, 4),
              u4{}, u4{}};
  }
  return {};
}

// c0 + (((c1 − c0)·w) >> 4), floor shift. The result lies between c0 and c1, so it is an 8-bit value.
constexpr u8 lerp16_4(u8 c0, u8 c1, u4 w) noexcept {
  const fixed::s9 diff = c1 - c0;
  const auto step = fixed::shift_right<fixed::rounding::floor, 4>(diff * w);  // s13 >> 4 -> s9
  return (c0 + step).narrow<8, fixed::signedness::is_unsigned, fixed::overflow::wrap>();
}

constexpr rgba8 lerp16_4(rgba8 c0, rgba8 c1, u4 w) noexcept {
  return {lerp16_4(c0.r, c1.r, w), lerp16_4(c0.g, c1.g, w), lerp16_4(c0.b, c1.b, w), lerp16_4(c0.a, c1.a, w)};
}

// Texels t00 = (u0, v0), t10 = (u0 + 1, v0), t01 = (u0, v0 + 1), t11 = (u0 + 1, v0 + 1):
// horizontal lerps first, then the vertical one.
constexpr rgba8 bilinear_filter(rgba8 t00, rgba8 t10, rgba8 t01, rgba8 t11, u4 wu, u4 wv) noexcept {
  return lerp16_4(lerp16_4(t00, t10, wu), lerp16_4(t01, t11, wu), wv);
}

// The one-step sum: floor(((16 − wu)(16 − wv)·t00 + wu(16 − wv)·t10 + (16 − wu)wv·t01 + wu·wv·t11) / 256)
// per channel. The weights sum to 256, so the result lies in 0..255.
constexpr u8 weighted_sum_4(u8 t00, u8 t10, u8 t01, u8 t11, u4 wu, u4 wv) noexcept {
  const int a = wu.value(), b = wv.value();
  const int sum =
      (16 - a) * (16 - b) * t00.value() + a * (16 - b) * t10.value() + (16 - a) * b * t01.value() + a * b * t11.value();
  return u8::from_wrapped(fixed::shift_right<fixed::rounding::floor>(std::int64_t{sum}, 8));
}
constexpr rgba8 weighted_sum_4(rgba8 t00, rgba8 t10, rgba8 t01, rgba8 t11, u4 wu, u4 wv) noexcept {
  return {weighted_sum_4(t00.r, t10.r, t01.r, t11.r, wu, wv), weighted_sum_4(t00.g, t10.g, t01.g, t11.g, wu, wv),
          weighted_sum_4(t00.b, t10.b, t01.b, t11.b, wu, wv), weighted_sum_4(t00.a, t10.a, t01.a, t11.a, wu, wv)};
}
// One filtered sample; `fetch(u, v)` returns the texel at integer coordinates (wrap/clamp is the
// caller's: CLAMP_1 is not modelled here). CLUT lookups happen inside fetch, before filtering.
template <typename Fetch>
constexpr rgba8 sample(Fetch&& fetch, std::int32_t u16, std::int32_t v16, bilinear_mode mode) {
  const texel_footprint f = footprint(u16, v16, mode);
  if (mode == bilinear_mode::nearest) return fetch(f.u0, f.v0);
  if (mode == bilinear_mode::weighted_sum_4)
    return weighted_sum_4(fetch(f.u0, f.v0), fetch(f.u0 + 1, f.v0), fetch(f.u0, f.v0 + 1), fetch(f.u0 + 1, f.v0 + 1),
                          f.wu, f.wv);
  return bilinear_filter(fetch(f.u0, f.v0), fetch(f.u0 + 1, f.v0), fetch(f.u0, f.v0 + 1), fetch(f.u0 + 1, f.v0 + 1),
                         f.wu, f.wv);
}

}  // namespace gs

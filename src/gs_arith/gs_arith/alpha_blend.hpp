// gs_arith/alpha_blend.hpp — ALPHA_1: Cv = ((A − B)·C >> 7) + D per RGB channel.
//
// Evidence (../shared/spec/gs-alu-facts.md, "Alpha blend"): HW-confirmed for COLCLAMP = 1 by the 486 ps2autotests
// results (81 ABCD modes × 6 colour pairs): the shift is floor, C is used unclamped up to 0xFF.
// A, B, D ∈ {Cs, Cd, 0}; C ∈ {As, Ad, FIX}; the output alpha is As (alpha is never blended).
// Widths: A − B is s9 (−255..255), ·C is s17, >> 7 is s10, + D is s11 (−509..763).
#pragma once

#include <cstdint>

#include "fixed/integer.hpp"
#include "fixed/rounding.hpp"
#include "gs_arith/colour.hpp"
#include "gs_arith/options.hpp"

namespace gs {

// ALPHA_1.A, .B, .D selectors (2 bits; 3 is reserved).
enum class blend_colour : std::uint8_t { Cs = 0, Cd = 1, zero = 2 };
// ALPHA_1.C selector (2 bits; 3 is reserved).
enum class blend_alpha : std::uint8_t { As = 0, Ad = 1, FIX = 2 };

struct alpha_reg {
  blend_colour A = blend_colour::Cs;
  blend_colour B = blend_colour::Cd;
  blend_alpha C = blend_alpha::As;
  blend_colour D = blend_colour::Cd;
  u8 FIX{};
  friend constexpr bool operator==(const alpha_reg&, const alpha_reg&) = default;
};

// One channel: ((a − b)·c >> 7) + d, the shift as the option says (floor is the hardware's).
constexpr s11 blend_channel(u8 a, u8 b, u8 c, u8 d, blend_shift shift) noexcept {
  const fixed::s9 diff = a - b;
  const fixed::s17 product = diff * c;
  const auto r = shift == blend_shift::floor ? fixed::rounding::floor : fixed::rounding::toward_zero;
  const fixed::s10 scaled =
      fixed::shift_right<7>(product, r).narrow<10, fixed::signedness::is_signed, fixed::overflow::wrap>();
  return scaled + d;
}

constexpr u8 select_colour(blend_colour sel, u8 cs, u8 cd) noexcept {
  switch (sel) {
    case blend_colour::Cs: return cs;
    case blend_colour::Cd: return cd;
    case blend_colour::zero: return u8{};
  }
  return u8{};
}

constexpr u8 select_alpha(blend_alpha sel, u8 as, u8 ad, u8 fix) noexcept {
  switch (sel) {
    case blend_alpha::As: return as;
    case blend_alpha::Ad: return ad;
    case blend_alpha::FIX: return fix;
  }
  return u8{};
}

// The blend of source colour cs (after the texture function) over the frame-buffer colour cd.
// `ad` is the destination alpha as the blender reads it (0x80 for 24-bit targets: see frame_write).
constexpr rgb_wide alpha_blend(const alpha_reg& reg, rgba8 cs, rgba8 cd, const model_options& o) noexcept {
  const u8 c = select_alpha(reg.C, cs.a, cd.a, reg.FIX);
  auto channel = [&](u8 s, u8 d) {
    return blend_channel(select_colour(reg.A, s, d), select_colour(reg.B, s, d), c, select_colour(reg.D, s, d),
                         o.shift);
  };
  return {channel(cs.r, cd.r), channel(cs.g, cd.g), channel(cs.b, cd.b)};
}

// Blending off (PRIM.ABE = 0), or skipped by PABE: the source colour passes.
constexpr rgb_wide blend_off(rgba8 cs) noexcept { return {cs.r, cs.g, cs.b}; }

}  // namespace gs

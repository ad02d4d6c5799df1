// gs_arith/texture_function.hpp — TEX0.TFX / TEX0.TCC: texel Ct combined with the fragment colour Cf.
//
// Evidence (../shared/spec/gs-alu-facts.md, "Texture function"; matrix rows tfx_rounding, gouraud_fraction and
// highlight_clamp of docs/evidence.md): PCSX2 SW (GSDrawScanline.cpp CDrawScanline "AlphaTFX" /
// "ColorTFX": modulate16 then clamp8, addus8 for HIGHLIGHT alpha), the PCSX2 HW shaders
// (common/tfx_ps_tfx.inc tfx(): min(C_out, 255)) and Play! (GSH_VulkanDrawDesktop.cpp: Clamp to 1.0
// after the function) agree on the table below; hardware (ps2autotests simpletexture) confirms only
// MODULATE 0x80·0x80, TCC = RGB.
//   MODULATE   RGB min(255, (Ct·Cf) >> 7)          A (TCC=1) min(255, (At·Af) >> 7)
//   DECAL      RGB Ct                              A (TCC=1) At
//   HIGHLIGHT  RGB min(255, ((Ct·Cf) >> 7) + Af)   A (TCC=1) min(255, At + Af)
//   HIGHLIGHT2 RGB min(255, ((Ct·Cf) >> 7) + Af)   A (TCC=1) At
//   TCC = 0 (RGB): A = Af for every function.
// The clamp to 255 happens right after the function, before the alpha test and the blend: the paper
// (section 3.2) states "clamping to 8 bit is performed once after the texture function operation".
// DobieStation (gsthread.cpp tex_lookup, 3a23544b) clamps (Ct·Cf) >> 7 but adds Af after the clamp
// without clamping again (HIGHLIGHT RGB and alpha up to 0x1FE; issue 17: Ct 0xff, Cf 0x7f, Af 0x7f
// gives 0x17c): an emulator defect by that sentence of the paper and the three other implementations,
// so it is not a model option.
#pragma once

#include <cstdint>

#include "fixed/integer.hpp"
#include "fixed/rounding.hpp"
#include "gs_arith/colour.hpp"
#include "gs_arith/options.hpp"

namespace gs {

enum class tfx : std::uint8_t { MODULATE = 0, DECAL = 1, HIGHLIGHT = 2, HIGHLIGHT2 = 3 };
enum class tcc : std::uint8_t { RGB = 0, RGBA = 1 };

// A Gouraud/flat fragment colour channel in 8.7 fixed point (0 .. 255 + 127/128): 15 bits unsigned.
using gouraud_channel = fixed::uint<15>;
struct fragment_colour {
  gouraud_channel r, g, b, a;
  // A flat colour (vertex colour of a sprite, RGBAQ): the fraction bits are zero.
  static constexpr fragment_colour flat(rgba8 c) noexcept {
    auto up = [](u8 v) { return gouraud_channel::from_wrapped(v.value() << 7); };
    return {up(c.r), up(c.g), up(c.b), up(c.a)};
  }
  friend constexpr bool operator==(const fragment_colour&, const fragment_colour&) = default;
};

// The integer part of an 8.7 channel (what the blend and the alpha test see of Cf).
constexpr u8 integer_part(gouraud_channel c) noexcept { return u8::from_wrapped(c.value() >> 7); }

// (Ct·Cf) >> 7 for one channel, with Cf in 8.7: (Ct·Cf_8.7) >> 14 when the fraction is kept,
// (Ct·(Cf_8.7 >> 7)) >> 7 when it is truncated first. Range 0..511 (9 bits), before the clamp.
constexpr fixed::uint<9> modulate_channel(u8 ct, gouraud_channel cf, const model_options& o) noexcept {
  const auto r = o.tfx == tfx_rounding::floor ? fixed::rounding::floor : fixed::rounding::toward_zero;
  if (o.gouraud == gouraud_fraction::keep_fraction) {
    const auto p = ct * cf;  // u23
    return fixed::shift_right<14>(p, r).narrow<9, fixed::signedness::is_unsigned, fixed::overflow::wrap>();
  }
  const auto p = ct * integer_part(cf);  // u16
  return fixed::shift_right<7>(p, r).narrow<9, fixed::signedness::is_unsigned, fixed::overflow::wrap>();
}

// The clamp to 255 after the texture function.
template <int N>
constexpr u8 clamp_255(fixed::uint<N> v) noexcept {
  return v.template narrow<8, fixed::signedness::is_unsigned, fixed::overflow::saturate>();
}

// TFX × TCC on one texel. With texturing off (PRIM.TME = 0) the GS passes Cf instead: see
// texture_off().
constexpr rgba8 texture_function(tfx fn, tcc cc, rgba8 ct, fragment_colour cf, const model_options& o) noexcept {
  const u8 af = integer_part(cf.a);
  auto rgb = [&](u8 t, gouraud_channel f) -> u8 {
    switch (fn) {
      case tfx::MODULATE: return clamp_255(modulate_channel(t, f, o));
      case tfx::DECAL: return t;
      case tfx::HIGHLIGHT:
      case tfx::HIGHLIGHT2: return clamp_255(modulate_channel(t, f, o) + af);
    }
    return t;
  };
  u8 a = af;
  if (cc == tcc::RGBA) {
    switch (fn) {
      case tfx::MODULATE: a = clamp_255(modulate_channel(ct.a, cf.a, o)); break;
      case tfx::DECAL: a = ct.a; break;
      case tfx::HIGHLIGHT: a = clamp_255(ct.a + af); break;
      case tfx::HIGHLIGHT2: a = ct.a; break;
    }
  }
  return {rgb(ct.r, cf.r), rgb(ct.g, cf.g), rgb(ct.b, cf.b), a};
}

// PRIM.TME = 0: the fragment colour's integer part passes unchanged.
constexpr rgba8 texture_off(fragment_colour cf) noexcept {
  return {integer_part(cf.r), integer_part(cf.g), integer_part(cf.b), integer_part(cf.a)};
}

}  // namespace gs

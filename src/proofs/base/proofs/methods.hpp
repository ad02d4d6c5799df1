// proofs/methods.hpp — the paper's GS passes, composed from the model's unit functions
// (gs::texture_function, gs::alpha_blend, gs::colclamp, gs::frame_write). Nothing here re-derives a
// formula: each step is the register set the paper describes, run through the model; the sets are
// gs_methods/pass_registers.hpp's, the ones the renderer and the dump writer draw with (pass_table.hpp).
//
// Post filters (section 3.3, step 2.4) are modelled at VALUE level: the paper fetches channels with
// the PSMT8 / PSMT8H channel shuffle and adds them with additive blends (A = Cs, B = 0, C = FIX 0x80,
// D = Cd) with COLCLAMP off; here each addition is that blend on one channel, but the memory-layout
// part (which texel lands on which pixel) is not modelled — the channel fetch itself belongs to the
// pipeline area.
#pragma once

#include <cstdint>

#include "gs_arith/alpha_blend.hpp"
#include "gs_arith/colclamp.hpp"
#include "gs_arith/colour.hpp"
#include "gs_arith/frame_write.hpp"
#include "gs_arith/options.hpp"
#include "gs_arith/texture_function.hpp"
#include "gs_methods/pass_registers.hpp"

namespace gsdot3::proofs::methods {

using fixed::u8;
using gs::rgba8;

constexpr u8 byte(int v) noexcept { return u8::from_wrapped(v); }
constexpr rgba8 grey(int rgb, int a) noexcept { return {byte(rgb), byte(rgb), byte(rgb), byte(a)}; }

// ---- eq. (8) and the four-pass passes 2-4 ------------------------------------------------------
// Blend (Cs − Cd)·As + Cd: A = Cs, B = Cd, C = As, D = Cd (the four-pass axis passes' ALPHA_1).
inline constexpr gs::alpha_reg offset_multiply_blend = gs_methods::signed_multiply;

// Eq. (8) on one channel before COLCLAMP: Cs = 0x80 (the reordered palette's RGB), As = b2,
// Cd = a2. Returns the s11 blend output.
constexpr fixed::s11 offset_multiply(u8 a2, u8 b2, const gs::model_options& o) noexcept {
  const rgba8 cs{byte(0x80), byte(0x80), byte(0x80), b2};
  const rgba8 cd{a2, a2, a2, u8{}};
  return gs::alpha_blend(offset_multiply_blend, cs, cd, o).r;
}

// A DPB pass drawing the texel (0x80, 0x80, 0x80, a) through pass p's registers (TFX = DECAL, TCC =
// RGBA: Cs is the texel) over the PSMCT32 DPB word, COLCLAMP as p says, written with p's FBMSK.
// Returns the new DPB word.
constexpr std::uint32_t grey_alpha_pass(const gs_methods::pass_regs& p, std::uint32_t dpb, u8 a,
                                        const gs::model_options& o) noexcept {
  const rgba8 texel{byte(0x80), byte(0x80), byte(0x80), a};
  const rgba8 cs = gs::texture_function(p.TFX, p.TCC, texel, gs::fragment_colour::flat(grey(0x80, 0x80)), o);
  const rgba8 cd = gs::frame_read(gs::frame_psm::PSMCT32, dpb);
  const rgba8 out = gs::colclamp(gs::alpha_blend(p.ALPHA, cs, cd, o), cs.a, p.CLAMP);
  return gs::frame_write(gs::frame_psm::PSMCT32, out, dpb, p.FBMSK);
}

// One four-pass signed-multiplication pass (section 3.6, passes 2-4): the reordered palette texel
// (0x80, 0x80, 0x80, b2) blended over the DPB word with COLCLAMP off (step 2.2), written with FBMSK
// keeping every channel but `channel` (0 = R, 1 = G, 2 = B) and the alpha byte. The registers are
// gs_methods' four_pass_x, _y and _z.
constexpr std::uint32_t four_pass_channel(std::uint32_t dpb, int channel, u8 b2, const gs::model_options& o) noexcept {
  constexpr const gs_methods::pass_regs* axis[3] = {&gs_methods::four_pass_x, &gs_methods::four_pass_y,
                                                    &gs_methods::four_pass_z};
  return grey_alpha_pass(*axis[channel], dpb, b2, o);
}

// Section 3.6's spot-light attenuation of a DPB word: the intensity texel (0x80, 0x80, 0x80, a),
// blended (Cd − Cs)·As + Cs with COLCLAMP off, RGB written, alpha kept (gs_methods' spot_attenuation).
// a = 128·scale.
constexpr std::uint32_t spot_attenuate(std::uint32_t dpb, u8 a, const gs::model_options& o) noexcept {
  return grey_alpha_pass(gs_methods::spot_attenuation, dpb, a, o);
}

// ---- two-pass (section 3.5) ----------------------------------------------------------------------
// Pass 1: positive palette texel, TFX = MODULATE with the Gouraud/flat light colour, blending off,
// COLCLAMP off (gs_methods' two_pass_positive). Returns the DPB colour.
constexpr rgba8 two_pass_pass1(rgba8 pos_texel, gs::fragment_colour light, const gs::model_options& o) noexcept {
  constexpr const gs_methods::pass_regs& p = gs_methods::two_pass_positive;
  static_assert(!p.ABE);
  const rgba8 cs = gs::texture_function(p.TFX, p.TCC, pos_texel, light, o);
  return gs::colclamp(gs::blend_off(cs), cs.a, p.CLAMP);
}

// Pass 2 blend: Cd − Cs (A = Cd, B = Cs, C = FIX = 0x80, D = 0): two_pass_negative's ALPHA_1.
inline constexpr gs::alpha_reg subtract_blend = gs_methods::subtract_source;

// Pass 2 up to the blend: negative palette texel (alpha n'_a), TFX = MODULATE, TCC = RGBA, the light
// colour with vertex alpha 0x80. Returns the blend output before COLCLAMP and the source alpha As.
struct pass2_result {
  gs::rgb_wide wide;
  u8 as;
};
constexpr pass2_result two_pass_pass2_wide(rgba8 neg_texel, gs::fragment_colour light, rgba8 dpb,
                                           const gs::model_options& o) noexcept {
  constexpr const gs_methods::pass_regs& p = gs_methods::two_pass_negative;
  light.a = gs::gouraud_channel::from_wrapped(0x80 << 7);
  const rgba8 cs = gs::texture_function(p.TFX, p.TCC, neg_texel, light, o);
  return {gs::alpha_blend(p.ALPHA, cs, dpb, o), cs.a};
}
// Pass 2 written: COLCLAMP off (wrap), output alpha As.
constexpr rgba8 two_pass_pass2(rgba8 neg_texel, gs::fragment_colour light, rgba8 dpb,
                               const gs::model_options& o) noexcept {
  const auto p = two_pass_pass2_wide(neg_texel, light, dpb, o);
  return gs::colclamp(p.wide, p.as, gs_methods::two_pass_negative.CLAMP);
}

// ---- three-pass (section 3.5's alternative) ------------------------------------------------------
// Pass 3: the terms palette texel (128 + Max(−n, 0) − Max(n, 0) per channel) through TFX = DECAL,
// blended Cs + Cd over the DPB after pass 2, COLCLAMP off (gs_methods' three_pass_add_terms). Returns
// the blend output before COLCLAMP.
constexpr gs::rgb_wide three_pass_pass3_wide(rgba8 terms_texel, rgba8 dpb, const gs::model_options& o) noexcept {
  constexpr const gs_methods::pass_regs& p = gs_methods::three_pass_add_terms;
  const rgba8 cs = gs::texture_function(p.TFX, p.TCC, terms_texel, gs::fragment_colour::flat(grey(0x80, 0x80)), o);
  return gs::alpha_blend(p.ALPHA, cs, dpb, o);
}
// Pass 3 written: COLCLAMP off (wrap), the DPB alpha kept (FBMSK).
constexpr rgba8 three_pass_pass3(rgba8 terms_texel, rgba8 dpb, const gs::model_options& o) noexcept {
  constexpr const gs_methods::pass_regs& p = gs_methods::three_pass_add_terms;
  const rgba8 out = gs::colclamp(three_pass_pass3_wide(terms_texel, dpb, o), dpb.a, p.CLAMP);
  return gs::frame_read(gs::frame_psm::PSMCT32, gs::frame_write(gs::frame_psm::PSMCT32, out, dpb.to_u32(), p.FBMSK));
}

// ---- post filters (value level, see the header comment) ---------------------------------------
// Additive blend Cs + Cd: A = Cs, B = 0, C = FIX = 0x80, D = Cd: the post filter's ALPHA_1 (post_add_into_red).
inline constexpr gs::alpha_reg add_blend = gs_methods::add_source;
// x + y on one channel with COLCLAMP off.
constexpr u8 add_wrapped(u8 x, u8 y, const gs::model_options& o) noexcept {
  const auto w = gs::alpha_blend(add_blend, grey(x.value(), 0), grey(y.value(), 0), o);
  return gs::colclamp_channel(w.r, false);
}
// Four-pass / eq. (9) post filter: r + g + b (mod 256).
constexpr u8 sum_rgb(rgba8 c, const gs::model_options& o) noexcept {
  return add_wrapped(add_wrapped(c.r, c.g, o), c.b, o);
}
// Two-pass post filter: alpha (read as PSMT8H) added to r, g and b, then r + g + b.
constexpr u8 sum_rgb_plus_3a(rgba8 c, const gs::model_options& o) noexcept {
  return sum_rgb({add_wrapped(c.r, c.a, o), add_wrapped(c.g, c.a, o), add_wrapped(c.b, c.a, o), c.a}, o);
}

// Section 3.3's "− 128" done on the GS: the constant 0x80 subtracted by the blend Cd − Cs.
constexpr u8 minus_128(u8 v, const gs::model_options& o) noexcept {
  const auto w = gs::alpha_blend(subtract_blend, grey(0x80, 0), grey(v.value(), 0), o);
  return gs::colclamp_channel(w.r, false);
}

// ---- intensity look-up palette (section 3.3) ---------------------------------------------------
// The paper's ILP: 1, 2, ..., 128 in the first 128 entries, zeros after (index = dot product as a
// signed byte). The offset-keeping ILP is indexed by dot + 128 (mod 256).
constexpr int ilp_entry(int index) noexcept { return index < 128 ? index + 1 : 0; }
constexpr int ilp_offset_entry(int index) noexcept { return ilp_entry((index + 128) & 0xFF); }

// The byte a post filter leaves, read as the signed dot product it encodes.
constexpr int as_signed(u8 v) noexcept { return v.value() >= 128 ? v.value() - 256 : v.value(); }

}  // namespace gsdot3::proofs::methods

// pipeline/pass_table.hpp — the one description of the methods' passes: the register set of every
// pass (pass_regs, context 1), the clear values and write masks, and the per-vertex colour and
// texture coordinates each triangle pass sends. render.cpp draws with them directly; frame_packets.cpp
// writes the same values as GIF packets (TEX0_1.TFX/TCC, PRIM.TME/ABE, ALPHA_1, COLCLAMP,
// FRAME_1.FBMSK; RGBAQ, UV per vertex), so the two cannot disagree on a pass.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "gs_arith/colour.hpp"
#include "gs_arith/depth_test.hpp"
#include "pipeline/encoders.hpp"
#include "pipeline/gs_pass.hpp"
#include "pipeline/prepare.hpp"

namespace gsdot3::pipeline::passes {

using gs::blend_alpha;
using gs::blend_colour;

// The depth test of the methods (section 3.1): TEST_1.ZTE = 1, ZTST = GEQUAL (larger Z is nearer);
// ZBUF_1.PSM = PSMZ24 (the prepared Z planes are 24-bit, 0..0xFFFFFF, so Z24 holds them exactly and
// the clamp never acts; the layout is PSMZ32's), ZMSK = 0 in step 1 (Z written), 1 in every later pass.
// The Z clear before step 1 is a sprite with Z = 0 and ZTST = ALWAYS. frame_packets.cpp writes
// these as TEST_1 and ZBUF_1.
inline constexpr gs::test_reg depth_gequal{false, gs::atst::NEVER, {}, gs::afail::KEEP, false, false, true, gs::ztst::GEQUAL};
inline constexpr gs::test_reg depth_always{false, gs::atst::NEVER, {}, gs::afail::KEEP, false, false, true, gs::ztst::ALWAYS};
inline constexpr gs::zbuf_reg z_written{{}, gs::zbuf_psm::PSMZ24, false};
inline constexpr gs::zbuf_reg z_masked{{}, gs::zbuf_psm::PSMZ24, true};

inline constexpr std::uint32_t clear_dpb = 0x00808080u;        // step 2.1
inline constexpr std::uint32_t keep_alpha = 0xFF000000u;       // FBMSK: write RGB only
inline constexpr std::uint32_t only_channel[3] = {0xFFFFFF00u, 0xFFFF00FFu, 0xFF00FFFFu};  // FBMSK: R, G, B only

// ALPHA_1 settings used by the methods.
inline constexpr gs::alpha_reg add_source{blend_colour::Cs, blend_colour::zero, blend_alpha::FIX, blend_colour::Cd,
                                          gs::u8::literal(0x80)};  // Cs + Cd
inline constexpr gs::alpha_reg subtract_source{blend_colour::Cd, blend_colour::Cs, blend_alpha::FIX, blend_colour::zero,
                                               gs::u8::literal(0x80)};  // Cd − Cs
inline constexpr gs::alpha_reg signed_multiply{blend_colour::Cs, blend_colour::Cd, blend_alpha::As, blend_colour::Cd,
                                               gs::u8{}};  // (Cs − Cd)·As + Cd, section 3.6
inline constexpr gs::alpha_reg multiply_by_ad{blend_colour::Cs, blend_colour::zero, blend_alpha::Ad, blend_colour::zero,
                                              gs::u8{}};  // Cs·Ad, step 4

// The register sets of the passes. Each is a constant the pass loops are instantiated with, so the
// compiler folds gs::pixel_pipeline for it (the same model function, specialised, not a copy).
//                                                     TME    ABE    TFX                 TCC             ALPHA_1          CLAMP  FBMSK
inline constexpr pass_regs step1_ambient{};  // TME = 0, ABE = 0, COLCLAMP = 1; also the flat fills (sprites)
inline constexpr pass_regs two_pass_positive{          true,  false, gs::tfx::MODULATE,  gs::tcc::RGB,   {},              false, 0};
inline constexpr pass_regs two_pass_negative{          true,  true,  gs::tfx::MODULATE,  gs::tcc::RGBA,  subtract_source, false, 0};
inline constexpr pass_regs two_pass_add_alpha{         true,  true,  gs::tfx::DECAL,     gs::tcc::RGB,   add_source,      false, keep_alpha};
inline constexpr pass_regs four_pass_sphere{           true,  false, gs::tfx::HIGHLIGHT, gs::tcc::RGB,   {},              false, keep_alpha};
inline constexpr pass_regs four_pass_x{                true,  true,  gs::tfx::DECAL,     gs::tcc::RGBA,  signed_multiply, false, only_channel[0]};
inline constexpr pass_regs four_pass_y{                true,  true,  gs::tfx::DECAL,     gs::tcc::RGBA,  signed_multiply, false, only_channel[1]};
inline constexpr pass_regs four_pass_z{                true,  true,  gs::tfx::DECAL,     gs::tcc::RGBA,  signed_multiply, false, only_channel[2]};
inline constexpr pass_regs baseline_add{               true,  true,  gs::tfx::MODULATE,  gs::tcc::RGB,   add_source,      false, keep_alpha};
inline constexpr pass_regs baseline_subtract{          true,  true,  gs::tfx::MODULATE,  gs::tcc::RGB,   subtract_source, false, keep_alpha};
inline constexpr pass_regs post_add_into_red{          true,  true,  gs::tfx::DECAL,     gs::tcc::RGB,   add_source,      false, only_channel[0]};
inline constexpr pass_regs ilp_into_lab{               true,  true,  gs::tfx::MODULATE,  gs::tcc::RGB,   add_source,      true,  keep_alpha};
inline constexpr pass_regs diffuse_layer{              true,  false, gs::tfx::DECAL,     gs::tcc::RGB,   {},              true,  0};
inline constexpr pass_regs multiply_red{               true,  true,  gs::tfx::DECAL,     gs::tcc::RGB,   multiply_by_ad,  true,  only_channel[0]};
inline constexpr pass_regs multiply_green{             true,  true,  gs::tfx::DECAL,     gs::tcc::RGB,   multiply_by_ad,  true,  only_channel[1]};
inline constexpr pass_regs multiply_blue{              true,  true,  gs::tfx::DECAL,     gs::tcc::RGB,   multiply_by_ad,  true,  only_channel[2]};
inline constexpr pass_regs move_into_alpha{            true,  false, gs::tfx::DECAL,     gs::tcc::RGBA,  {},              true,  0x00FFFFFFu};  // memory path, step 4

inline gs::rgba8 rgb(int r, int g, int b, int a) {
  return {gs::u8::from_wrapped(r), gs::u8::from_wrapped(g), gs::u8::from_wrapped(b), gs::u8::from_wrapped(a)};
}
inline const gs::rgba8 white = rgb(0x80, 0x80, 0x80, 0x80);

// The vertex colours of the triangle passes (RGBAQ), from the light's per-vertex data.
// Two-pass (section 3.5): the tolight vector · fade_att packed as signed chars of scale s.
inline gs::rgba8 two_pass_colour(const light_vertex& l, int s) { return pack_tolight(l.T * l.fade, s); }
// Four-pass sphere pass, HIGHLIGHT: sph·scale + (1 − scale)·128 with scale = fade_att in 1/128.
inline gs::rgba8 four_pass_sphere_colour(const light_vertex& l) {
  const int scale = std::clamp(static_cast<int>(std::lround(l.fade * 128.0f)), 0, 128);
  return rgb(scale, scale, scale, 128 - scale);
}
// Baseline (section 2): TL_pos / TL_neg = nearest(127·max(±T·fade, 0)) per component, alpha 0x80.
inline gs::rgba8 baseline_colour(const light_vertex& l, bool negative) {
  const glm::vec3 t = l.T * l.fade * (negative ? -1.0f : 1.0f);
  return rgb(nearest(std::max(t.x, 0.0f) * 127), nearest(std::max(t.y, 0.0f) * 127), nearest(std::max(t.z, 0.0f) * 127), 0x80);
}

// The texture coordinates (UV, 12.4 texels) per triangle corner: the normal map's, or the 64×64
// sphere map's from the vertex's tolight vector.
inline std::array<std::int32_t, 2> normal_map_uv(const prepared_triangle& t, int k) { return t.uv16[static_cast<std::size_t>(k)]; }
inline std::array<std::int32_t, 2> sphere_uv(const light_vertex& l) {
  const st c = sphere_coordinates(l.T);
  return {static_cast<std::int32_t>(std::lround(c.s * 64 * 16)), static_cast<std::int32_t>(std::lround(c.t * 64 * 16))};
}

}  // namespace gsdot3::pipeline::passes

// gs_methods/pass_registers.hpp — the register sets of the paper's GS passes (seed 000), one
// description for every layer: pipeline/pass_table.hpp lists them per method for the renderer, the dump
// writer and the tests, and proofs/methods.hpp runs the same sets through the model's units for the
// catalogue's claims. Each set is what the paper's step writes (PRIM.TME/ABE, TEX0_1.TFX/TCC, ALPHA_1,
// COLCLAMP, FRAME_1.FBMSK); depth, texture and target are the passes' own (pass_table.hpp).
#pragma once

#include <cstdint>

#include "gs_arith/registers.hpp"

namespace gsdot3::gs_methods {

using gs::blend_alpha;
using gs::blend_colour;

// The registers a pass sets (context 1); everything else keeps gs_registers' neutral values, the
// frame buffer is PSMCT32.
struct pass_regs {
  bool TME = false;                 // PRIM.TME
  bool ABE = false;                 // PRIM.ABE
  gs::tfx TFX = gs::tfx::MODULATE;  // TEX0_1.TFX
  gs::tcc TCC = gs::tcc::RGB;       // TEX0_1.TCC
  gs::alpha_reg ALPHA{};            // ALPHA_1
  bool CLAMP = true;                // COLCLAMP.CLAMP
  std::uint32_t FBMSK = 0;          // FRAME_1.FBMSK

  constexpr gs::gs_registers registers() const noexcept {
    gs::gs_registers r;
    r.PRIM.TME = TME;
    r.PRIM.ABE = ABE;
    r.TEX0_1.TFX = TFX;
    r.TEX0_1.TCC = TCC;
    r.ALPHA_1 = ALPHA;
    r.COLCLAMP.CLAMP = CLAMP;
    r.FRAME_1.FBMSK = FBMSK;
    return r;
  }
};

inline constexpr std::uint32_t clear_dpb = 0x00808080u;                                    // step 2.1
inline constexpr std::uint32_t keep_alpha = 0xFF000000u;                                   // FBMSK: write RGB only
inline constexpr std::uint32_t only_channel[3] = {0xFFFFFF00u, 0xFFFF00FFu, 0xFF00FFFFu};  // FBMSK: R, G, B only

// The depth test of the methods (section 3.1): TEST_1.ZTE = 1, ZTST = GEQUAL (larger Z is nearer);
// ZBUF_1.PSM = PSMZ24 (the prepared Z planes are 24-bit, 0..0xFFFFFF, so Z24 holds them exactly and
// the clamp never acts; the layout is PSMZ32's), ZMSK = 0 in step 1 (Z written), 1 in every later pass.
// The Z clear before step 1 is a sprite with Z = 0 and ZTST = ALWAYS. pipeline/frame_packets.cpp writes
// these as TEST_1 and ZBUF_1.
inline constexpr gs::test_reg depth_gequal{false, gs::atst::NEVER, {},   gs::afail::KEEP,
                                           false, false,           true, gs::ztst::GEQUAL};
inline constexpr gs::test_reg depth_always{false, gs::atst::NEVER, {},   gs::afail::KEEP,
                                           false, false,           true, gs::ztst::ALWAYS};
inline constexpr gs::zbuf_reg z_written{{}, gs::zbuf_psm::PSMZ24, false};
inline constexpr gs::zbuf_reg z_masked{{}, gs::zbuf_psm::PSMZ24, true};

// ALPHA_1 settings used by the methods.
inline constexpr gs::alpha_reg add_source{blend_colour::Cs, blend_colour::zero, blend_alpha::FIX, blend_colour::Cd,
                                          gs::u8::literal(0x80)};  // Cs + Cd
inline constexpr gs::alpha_reg subtract_source{blend_colour::Cd, blend_colour::Cs, blend_alpha::FIX, blend_colour::zero,
                                               gs::u8::literal(0x80)};  // Cd − Cs
inline constexpr gs::alpha_reg signed_multiply{blend_colour::Cs, blend_colour::Cd, blend_alpha::As, blend_colour::Cd,
                                               gs::u8{}};  // (Cs − Cd)·As + Cd, section 3.6
// (Cd − Cs)·As + Cs with Cs = 128 and As = 128·scale: 128 − (128 − Cd)·scale, section 3.6's spot-light
// attenuation of the DPB "by using the GS blend mode ... in the same way as when using the HIGHLIGHT
// texture function" (seed 000, section 3.6; the paper names no selectors: these are the ones that
// give HIGHLIGHT's form, sph·scale + (1 − scale)·128).
inline constexpr gs::alpha_reg attenuate_about_source{blend_colour::Cd, blend_colour::Cs, blend_alpha::As,
                                                      blend_colour::Cs, gs::u8{}};
inline constexpr gs::alpha_reg multiply_by_ad{blend_colour::Cs, blend_colour::zero, blend_alpha::Ad, blend_colour::zero,
                                              gs::u8{}};  // Cs·Ad, step 4
// Cd·As: step 4 of section 3.1's one-buffer variant, the diffuse layer already in the frame buffer and
// the LAB channel read from a free alpha as the texel's alpha (the same blend product as Cs·Ad).
inline constexpr gs::alpha_reg multiply_destination_by_as{blend_colour::Cd, blend_colour::zero, blend_alpha::As,
                                                          blend_colour::zero, gs::u8{}};

// The register sets of the passes. Each is a constant the pass loops are instantiated with, so the
// compiler folds gs::pixel_pipeline for it (the same model function, specialised, not a copy).
//                                                     TME    ABE    TFX                 TCC             ALPHA_1 CLAMP
//                                                     FBMSK
inline constexpr pass_regs step1_ambient{};  // TME = 0, ABE = 0, COLCLAMP = 1; also the flat fills (sprites)
inline constexpr pass_regs two_pass_positive{true, false, gs::tfx::MODULATE, gs::tcc::RGB, {}, false, 0};
inline constexpr pass_regs two_pass_negative{true, true, gs::tfx::MODULATE, gs::tcc::RGBA, subtract_source, false, 0};
inline constexpr pass_regs two_pass_add_alpha{true, true, gs::tfx::DECAL, gs::tcc::RGB, add_source, false, keep_alpha};
// Section 3.5's three-pass alternative: "adding the terms as a separate additive pass" — the terms
// palette's 128 + Max(−n, 0) − Max(n, 0) per channel (DECAL), Cs + Cd, COLCLAMP off, alpha kept.
inline constexpr pass_regs three_pass_add_terms{true,       true,  gs::tfx::DECAL, gs::tcc::RGB,
                                                add_source, false, keep_alpha};
// Traditional Gouraud shading (section 4, figure 6b; step 5 and section 3.8): no texture, no blend,
// the interpolated vertex colour written into the DPB's RGB, COLCLAMP off.
inline constexpr pass_regs gouraud_dot{false, false, gs::tfx::MODULATE, gs::tcc::RGB, {}, false, keep_alpha};
inline constexpr pass_regs four_pass_sphere{true, false, gs::tfx::HIGHLIGHT, gs::tcc::RGB, {}, false, keep_alpha};
inline constexpr pass_regs four_pass_x{true,  true,           gs::tfx::DECAL, gs::tcc::RGBA, signed_multiply,
                                       false, only_channel[0]};
inline constexpr pass_regs four_pass_y{true,  true,           gs::tfx::DECAL, gs::tcc::RGBA, signed_multiply,
                                       false, only_channel[1]};
inline constexpr pass_regs four_pass_z{true,  true,           gs::tfx::DECAL, gs::tcc::RGBA, signed_multiply,
                                       false, only_channel[2]};
// Section 3.6's spot light: a projective texture of intensities, texel (128, 128, 128, 128·scale),
// drawn over the DPB after the sphere-map pass (or after all four passes), DECAL / RGBA, the
// attenuating blend, COLCLAMP off as every DPB pass of step 2, alpha kept.
inline constexpr pass_regs spot_attenuation{true,  true,      gs::tfx::DECAL, gs::tcc::RGBA, attenuate_about_source,
                                            false, keep_alpha};
// The same blend on the post filter's sum alone (red: the dot product + 128), after step 2.4: how the
// methods other than four-pass draw a spot light (the paper places it only in four-pass; a model
// choice, pipeline/pass_table.hpp's spot_step).
inline constexpr pass_regs spot_attenuation_red{
    true, true, gs::tfx::DECAL, gs::tcc::RGBA, attenuate_about_source, false, only_channel[0]};
inline constexpr pass_regs baseline_add{true, true, gs::tfx::MODULATE, gs::tcc::RGB, add_source, false, keep_alpha};
inline constexpr pass_regs baseline_subtract{true,  true,      gs::tfx::MODULATE, gs::tcc::RGB, subtract_source,
                                             false, keep_alpha};
inline constexpr pass_regs post_add_into_red{true,       true,  gs::tfx::DECAL, gs::tcc::RGB,
                                             add_source, false, only_channel[0]};
inline constexpr pass_regs ilp_into_lab{true, true, gs::tfx::MODULATE, gs::tcc::RGB, add_source, true, keep_alpha};
inline constexpr pass_regs diffuse_layer{true, false, gs::tfx::DECAL, gs::tcc::RGB, {}, true, 0};
inline constexpr pass_regs multiply_red{true,           true, gs::tfx::DECAL, gs::tcc::RGB,
                                        multiply_by_ad, true, only_channel[0]};
inline constexpr pass_regs multiply_green{true,           true, gs::tfx::DECAL, gs::tcc::RGB,
                                          multiply_by_ad, true, only_channel[1]};
inline constexpr pass_regs multiply_blue{true,           true, gs::tfx::DECAL, gs::tcc::RGB,
                                         multiply_by_ad, true, only_channel[2]};
// Step 5 (section 3.1): non-normal-mapped geometry drawn "as one generally would" into the output after
// step 4 — Gouraud vertex colours (PRIM.IIP = 1) times its texture, MODULATE, clamped, no blend; with
// ZTST = GEQUAL and ZMSK = 0 (it writes Z: it is the last pass of the frame).
inline constexpr pass_regs plain_gouraud{true, false, gs::tfx::MODULATE, gs::tcc::RGB, {}, true, 0};
// Section 3.1's one-buffer variant (pipeline draw_buffers::one): the output buffer's R, G, B written
// while its alpha keeps a dot layer or a LAB channel — flat fills (the LAB's ambient, step 3's clear),
// the diffuse layer, and step 4's multiply by a free alpha read as the texel's.
inline constexpr pass_regs flat_rgb{false, false, gs::tfx::MODULATE, gs::tcc::RGB, {}, true, keep_alpha};
inline constexpr pass_regs diffuse_layer_rgb{true, false, gs::tfx::DECAL, gs::tcc::RGB, {}, true, keep_alpha};
inline constexpr pass_regs multiply_red_by_as{
    true, true, gs::tfx::DECAL, gs::tcc::RGBA, multiply_destination_by_as, true, only_channel[0]};
inline constexpr pass_regs multiply_green_by_as{
    true, true, gs::tfx::DECAL, gs::tcc::RGBA, multiply_destination_by_as, true, only_channel[1]};
inline constexpr pass_regs multiply_blue_by_as{
    true, true, gs::tfx::DECAL, gs::tcc::RGBA, multiply_destination_by_as, true, only_channel[2]};
inline constexpr pass_regs move_into_alpha{true, false, gs::tfx::DECAL, gs::tcc::RGBA,
                                           {},   true,  0x00FFFFFFu};  // memory path, step 4; one buffer

}  // namespace gsdot3::gs_methods

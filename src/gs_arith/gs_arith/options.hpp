// gs_arith/options.hpp — every GS behaviour no hardware recording confirms, as a named run-time option.
//
// Defaults follow the facts digest ../shared/spec/gs-alu-facts.md; each enumerator names its evidence.
// Options are plain values passed to the unit functions, so the proofs can evaluate a claim under
// each of them without rebuilding.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gs {

// Rounding of the texture function's (Ct·Cf) >> 7 (evidence matrix: docs/evidence.md).
// floor: PCSX2 SW (GSDrawScanline.cpp CDrawScanline, modulate16 = arithmetic high multiply) and
//        DobieStation (gsthread.cpp multiply_tex_color, `>> 7`); confidence medium, no HW test beyond
//        0x80·0x80. truncate: PCSX2 HW shaders (common/tfx_ps_tfx.inc tfx(), `trunc((C * T) / 128)`).
//        Identical for non-negative inputs.
enum class tfx_rounding { floor, truncate };

// Gouraud colour into the texture function.
// keep_fraction: PCSX2 SW keeps the 8.7 colour, (Ct·Cf_8.7) >> 14 (default; unconfirmed on HW).
// truncate_to_8: the colour is truncated to 8 bits before the multiply (DobieStation tex_lookup:
//                the vertex colour has no fraction).
enum class gouraud_fraction { keep_fraction, truncate_to_8 };

// A Gouraud triangle's colour set-up (docs/evidence.md R9, which names the functions read and counts
// the sources per value; gs_arith/gouraud.hpp gouraud_colour).
// per_pixel_floor: the exact plane at every pixel, floored to whole 8.7 units (the value itself
//   truncated, as a float converted to an integer is: default, two sources, DobieStation gsthread.cpp
//   render_half_triangle `vtx_color.r = vtx.r` and Play!'s GPU `int(color * 255)`, both in float).
// per_pixel: the exact plane at every pixel with its distance from vertex 0's value truncated toward
//   zero to whole 8.7 units (one unit higher than per_pixel_floor where the colour falls away from
//   vertex 0 and the value is not whole; once credited to DobieStation and Play!, issue 53: no source).
// plane_steps: one plane per primitive, its start value at the bounding box's top-left pixel and both
//   steps truncated toward zero to whole 8.7 units, every pixel start + a·dx + b·dy (a fixed-point DDA
//   with 8.7 steps: the model's own, no source; a pixel far from the reference lags up to 16 levels
//   per axis).
// pcsx2_rows_4, pcsx2_rows_8: PCSX2 SW (GSRasterizer.cpp DrawTriangleSection, GSSetupPrimCodeGenerator
//   Color(), CDrawScanline): each row from the plane at its first pixel, truncated 16-bit lane offsets
//   and per-vector steps of 4 (SSE) or 8 (AVX2) pixels.
// per_pixel_level: parallel-gs (ubershader.comp compute_combined_color): the exact plane plus 1/256
//   level, floored to a whole level.
enum class gouraud_setup { plane_steps, per_pixel, pcsx2_rows_4, pcsx2_rows_8, per_pixel_level, per_pixel_floor };

// The blend's ((A − B)·C) >> 7. floor: HW-confirmed by all 486 ps2autotests blend results.
// truncate (toward zero): refuted by 24 of them; kept as a what-if for the proofs.
enum class blend_shift { floor, truncate };

// DIMX 3-bit entries. twos_complement −4..+3: PCSX2 GSRegs.h `s32 DM00:3` (default; SW and HW).
// sign_magnitude −3..+3, 4 is −0: DobieStation gsthread.cpp draw_pixel at commit 3a23544b.
// inverted_magnitude 4..7 -> −1..−4, −((dm & 3) + 1): DobieStation at commit 68dd073e as measured by
// issue 17's harness (that version was not readable here).
enum class dither_decode { twos_complement, sign_magnitude, inverted_magnitude };

// Which frame formats dithering applies to. sixteen_bit_only: PCSX2 SW (CDrawScanline `fpsm == 2 &&
// dthe`) and HW (GSRendererHW `dfmt == 2`) (default). all_formats: DobieStation draw_pixel (no format test).
enum class dither_targets { sixteen_bit_only, all_formats };

// Bilinear filtering arithmetic (docs/evidence.md R6 counts the sources). weighted_sum_4: 4-bit
// weights in one 2-D weighted sum, floor(Σ w·c / 256) (default: DobieStation tex_lookup, exact in its
// doubles; Play! Vulkan CDrawDesktop and parallel-gs's GPU sampler do the same sum in float).
// lerp16_4: PCSX2 SW `lerp16_4`, c0 + (((c1 − c0)·w) >> 4), horizontal then vertical. nearest:
// filtering off (what-if).
enum class bilinear_mode { lerp16_4, nearest, weighted_sum_4 };

// Which frame formats AFAIL = RGB_ONLY keeps the alpha of. thirty_two_bit_only: RGB_ONLY acts as
// FB_ONLY unless FRAME.PSM & 0xF == 0 (PCSX2 GSRegs.h GIFRegTEST::GetAFAIL, called with FRAME.PSM by
// GSRendererSW; PR 9652, tested against a PS2 per ../shared/spec/gs-alu-facts.md, "Alpha test"; default).
// all_formats: alpha (the A bit of 16-bit formats) is kept for every format (Play! GSH_VulkanDrawUtils.cpp
// CDrawUtils::AlphaTest, DobieStation draw_pixel at 3a23544b).
enum class rgb_only_targets { thirty_two_bit_only, all_formats };

// What a texture read sees of memory written earlier in the same draw (the GS's texture page buffer;
// section 3.4's Z-buffer clear writes the DPB while it is read as a texture). No hardware test.
// quarter_page: the buffer holds the 32×16-pixel quarter of the PSMCT32 page being read (2 KiB),
//   reloaded when a fetch leaves it; writes do not reach it (the paper's §3.4 explanation, "the
//   32x16 region that is currently being read as a texture (and is already cached)"; default).
// per_fragment: every fetch reads memory as written so far (no buffering; the strictest what-if).
// page: the buffer holds the whole 8 KiB page, reloaded when a fetch leaves it (what-if).
// draw_snapshot: the texture is read once before the draw (PCSX2's software renderer:
//   `GSRendererSW::SharedData::UpdateSource` converts the source texture before drawing).
enum class texture_buffer { quarter_page, per_fragment, page, draw_snapshot };

// Perspective texturing (PRIM.FST = 0, gs_arith/perspective.hpp; docs/evidence.md R10, R11 and
// docs/stq-evidence.md). No recording here has a Q other than 1.
// stq_range: S/Q (and T/Q) before scaling to texels. saturate_2047: clamped to ±2047 (default:
// parallel-gs ubershader.comp sample_texture; PCSX2 PR #12201's report of hardware tests: 2 sources).
// x86_int32: not clamped; a coordinate outside int32 at the conversion's scale becomes 0x80000000
// (PCSX2 SW cvttps2dq at 16.16; DobieStation's (int) cast on x86).
enum class stq_range_mode { saturate_2047, x86_int32 };
// stq_convert: texels to 12.4. truncate: toward zero at 1/16 texel (default: DobieStation gsthread.cpp
// render_half_triangle; PCSX2 PR #14078's hardware tests, Q = 1 only: 2 sources). floor_1_64:
// floor(texels·16 + 1/64) (parallel-gs sample_texture). trunc_16_16: toward zero at 1/65536 texel,
// then floored to 1/16 (PCSX2 SW SampleTexture: cvttps2dq, then the texel and 4-bit weight by shifts).
enum class stq_convert_mode { truncate, floor_1_64, trunc_16_16 };

// A UV plane's value at a pixel as the 12.4 texel coordinate (PRIM.FST = 1, sprites, and FST = 0
// with one Q, which the model interpolates as UV; gs_arith/uv_plane.hpp; docs/evidence.md R12), the
// plane as uv_plane interpolates it.
// floor: floor(16·U) (default: no bias; what the other sources' own interpolations do, R12).
// floor_1_64: floor(16·U + 1/64), a bias of 1/64 of a sixteenth before the floor (parallel-gs
//   ubershader.comp sample_texture, UV_EPSILON_PRE_SNAP, applied per pixel to the interpolated UV).
enum class uv_convert_mode { floor, floor_1_64 };
// How a UV plane is interpolated (the same planes as uv_convert; docs/evidence.md R13).
// exact: the rational value at the pixel centre (default: DobieStation render_half_triangle, Play!,
//   parallel-gs interpolate in float, which is this value up to float rounding: 3 sources).
// fixed_16: 16 fraction bits below 1/16 texel with floored gradients (MODEL-PLANE-16, rasteriser.hpp;
//   the nearest value to PCSX2 SW's 16.16 UV steps, GSSetupPrimCodeGenerator: 1 source).
enum class uv_plane_mode { exact, fixed_16 };

struct model_options {
  tfx_rounding tfx = tfx_rounding::floor;
  gouraud_fraction gouraud = gouraud_fraction::keep_fraction;
  gouraud_setup setup = gouraud_setup::per_pixel_floor;
  blend_shift shift = blend_shift::floor;
  dither_decode dither = dither_decode::twos_complement;
  dither_targets dither_on = dither_targets::sixteen_bit_only;
  bilinear_mode bilinear = bilinear_mode::weighted_sum_4;
  rgb_only_targets rgb_only = rgb_only_targets::thirty_two_bit_only;
  texture_buffer tex_buffer = texture_buffer::quarter_page;
  stq_range_mode stq_range = stq_range_mode::saturate_2047;
  stq_convert_mode stq_convert = stq_convert_mode::truncate;
  uv_convert_mode uv_convert = uv_convert_mode::floor;
  uv_plane_mode uv_plane = uv_plane_mode::exact;

  friend constexpr bool operator==(const model_options&, const model_options&) = default;
};

// One row per option: its name on the command line, its values (default first) and its evidence.
struct option_info {
  std::string_view name;
  std::vector<std::string_view> values;
  std::string_view evidence;
};
const std::vector<option_info>& option_catalogue();

// Sets option NAME to VALUE in `opts`; returns an error message for an unknown name or value.
std::optional<std::string> set_option(model_options& opts, std::string_view name, std::string_view value);
// The current value of option NAME, e.g. "floor".
std::string_view option_value(const model_options& opts, std::string_view name);

}  // namespace gs

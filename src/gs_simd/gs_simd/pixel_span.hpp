// gs_simd/pixel_span.hpp — the GS per-pixel units over spans of pixels with Google Highway, chosen at
// run time for the CPU (dynamic dispatch over the targets pixel_span.cpp is compiled for: AVX2, SSE4,
// SSSE3 and Highway's portable SCALAR fallback). The scalar units of src/gs_arith are the reference:
// every function here computes exactly what the gs_arith unit it names computes (tests/gs_simd).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "gs_arith/pixel_pipeline.hpp"

namespace gsdot3::simd {

// Pixels drawn with one register set, structure of arrays (the renderer's span, band_renderer.hpp).
// Lanes n .. capacity − 1 are computed too (on whatever they hold) and ignored.
struct pixel_batch {
  static constexpr std::size_t capacity = 64;
  std::size_t n = 0;
  alignas(64) std::uint32_t texel[capacity]{};  // Ct (A8B8G8R8)
  alignas(64) std::uint32_t cf[4][capacity]{};  // Cf r, g, b, a in 8.7
  alignas(64) std::uint32_t dst[capacity]{};    // the old frame-buffer word
  alignas(64) std::uint32_t x[capacity]{}, y[capacity]{};
  alignas(64) std::uint32_t out[capacity]{};  // gs::pixel_pipeline(...).out
};

// out[i] = gs::pixel_pipeline(regs, {cf[i], texel[i], dst[i], x[i], y[i]}, o).out for i < n.
void pixel_pipeline(const gs::gs_registers& regs, const gs::model_options& o, pixel_batch& batch);

// One unit over n lanes (n a multiple of unit_call::lane_multiple): for the unit tests and fuzz/alu_diff.
enum class unit {
  modulate,          // in0 = Ct, in1 = Cf (8.7)                    -> out0 = gs::modulate_channel
  texture_function,  // in0 = Ct word, in1..4 = Cf r, g, b, a       -> out0 = gs::texture_function word
  texture_off,       // in1..4 = Cf r, g, b, a                      -> out0 = gs::texture_off word
  alpha_test,        // in0 = A                                     -> out0 = rgb | a << 1 | z << 2
  frame_read,        // in0 = word                                  -> out0 = gs::frame_read word
  blend_channel,     // in0..3 = a, b, c, d                         -> out0 = gs::blend_channel
  alpha_blend,       // in0 = Cs word, in1 = Cd word                -> out0..2 = r, g, b (s11)
  dither_value,      // in0 = DIMX entry (0..7)                     -> out0 = gs::dither_value
  dither,            // in0..2 = r, g, b (s11), in3 = x, in4 = y    -> out0..2 = gs::dither
  colclamp,          // in0 = s11                                   -> out0 = gs::colclamp_channel
  apply_fba,         // in0 = word                                  -> out0 = gs::apply_fba word
  frame_pack,        // in0 = word                                  -> out0 = gs::frame_pack
  frame_mask,        // in0 = FBMSK                                 -> out0 = gs::frame_mask
  masked_merge,      // in0 = fresh, in1 = old, in2 = keep          -> out0 = gs::masked_merge
};
struct unit_call {
  static constexpr std::size_t lane_multiple = 16;
  unit which = unit::modulate;
  gs::gs_registers regs{};  // the fields the unit reads (TEX0_1.TFX/TCC, TEST_1, FRAME_1.PSM, ALPHA_1,
                            // DIMX, DTHE, COLCLAMP, FBA_1)
  gs::model_options options{};
  std::size_t n = 0;
  const std::int32_t* in[5] = {};
  std::int32_t* out[3] = {};
};
void run_unit(const unit_call& call);

// The SIMD targets compiled in and supported by this CPU, best first, and the one in use.
struct target {
  std::int64_t bits;
  std::string name;
};
std::vector<target> available_targets();
std::string current_target();
// Restricts dispatch to one target (a bit of available_targets()), or undoes it with 0 (tests).
void force_target(std::int64_t bits);

}  // namespace gsdot3::simd

// gs_arith/uv_plane.hpp — a UV plane and how its value at a pixel becomes the 12.4 texel coordinate
// gs::sample reads: the one rule (option uv_convert, docs/evidence.md R12) for every path that
// samples through UV planes — triangles with PRIM.FST = 1 (attribute_setup.hpp, so the renderer's
// scalar and SIMD paths, its value and memory paths and the packet interpreter), sprites
// (gs_packets/draw.cpp) and FST = 0 with one Q (perspective.hpp make_stq_sampler).
//
// No recording decides the rule: ../shared/hw has flat-colour sprite blends and one sprite texel at
// (0, 0), no interpolated UV near a texel boundary; ../shared/spec/gs-alu-facts.md says how the GS
// steps UV "is not recorded".
// - floor (default): floor(16·U), the plane's value with no bias (MODEL-PLANE-16, rasteriser.hpp).
// - floor_1_64: floor(16·U + 1/64) — parallel-gs gs/shaders/ubershader.comp `sample_texture`:
//   `floor(uv_1 * 16.0 + UV_EPSILON_PRE_SNAP)`, UV_EPSILON_PRE_SNAP = 1/64, applied per pixel to the
//   UV `compute_combined_color` interpolates ("Want a soft-floor here, not round behavior"; "Exact
//   rounding on hardware is somwhat unclear").
//
// How the plane is interpolated (option uv_plane, docs/evidence.md R13): `exact` keeps U as its
// rational value at the pixel centre (make_exact_plane), so floor(16·U + b) is exact and the bias is the
// plane's lift_1_64; `fixed_16` is MODEL-PLANE-16 (make_plane: 16 fraction bits below a sixteenth,
// gradients floored, so a value may land just below the exact one), whose value at a pixel, P = base +
// dx·x + dy·y, every evaluator takes as P >> 16 (plane::at, the row walk gs::attribute_walker that the
// SIMD path uses, the texture streamer's footprint). There the bias b is added to the plane's base,
// once: floor((P + b) / 2^16) = ((base + b) + dx·x + dy·y) >> 16 is an identity of integers, so each
// evaluator applies floor(16·U + 1/64) at every pixel without a second copy of the rule
// (tests/gs_arith/uv_plane_test.cpp checks both forms against exact rationals).
#pragma once

#include <array>
#include <cstdint>

#include "gs_arith/options.hpp"
#include "gs_arith/rasteriser.hpp"

namespace gs {

// The bias added before the floor, in plane units (2^-16 of a sixteenth of a texel).
constexpr std::int64_t uv_convert_bias(uv_convert_mode m) noexcept {
  return m == uv_convert_mode::floor_1_64 ? (std::int64_t{1} << 16) / 64 : 0;
}
static_assert(uv_convert_bias(uv_convert_mode::floor_1_64) * 64 == std::int64_t{1} << 16, "1/64 of a sixteenth");

// The 12.4 texel coordinate of a fixed_16 UV plane value P (plane units, before the ±2^20 clamp):
// floor((P + b) / 2^16).
constexpr std::int64_t uv_texel(std::int64_t p, uv_convert_mode m) noexcept { return (p + uv_convert_bias(m)) >> 16; }

// The two UV options, as every path that samples through UV planes reads them.
struct uv_rule {
  uv_plane_mode plane = uv_plane_mode::exact;
  uv_convert_mode convert = uv_convert_mode::floor;
};
constexpr uv_rule uv_rule_of(const model_options& o) noexcept { return {o.uv_plane, o.uv_convert}; }

// The UV plane through three vertex coordinates uv16 (12.4 texels) at the 12.4 positions p (non-zero
// area), clamped to ±2^20, whose plane::at(x, y) is the 12.4 texel coordinate under `r`.
inline plane make_uv_plane(const std::array<xy124, 3>& p, const std::array<std::int32_t, 3>& uv16, uv_rule r) {
  if (r.plane == uv_plane_mode::exact) {
    plane pl = make_exact_plane(p, uv16, -(1 << 20), 1 << 20);
    pl.lift_1_64 = r.convert == uv_convert_mode::floor_1_64;
    return pl;
  }
  plane pl = make_plane(p, uv16, -(1 << 20), 1 << 20);
  pl.base += uv_convert_bias(r.convert);
  return pl;
}

}  // namespace gs

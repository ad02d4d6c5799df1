// gs_arith/perspective.hpp — perspective-correct texturing (PRIM.FST = 0, Q varying over a triangle):
// S, T, Q at a pixel and their conversion to the 12.4 texel coordinates gs::sample reads.
//
// No PS2 recording here covers STQ; docs/stq-evidence.md lists what each emulator does (read with the
// search tool, 2026-12-06). What the model takes, and why:
// - Interpolation: S, T and Q are the exact planes through the three vertices' float32 values at the
//   pixel (the rasteriser's integer window coordinates), rounded to float32. The sources all
//   interpolate in float32, each in its own order (parallel-gs triangle_setup.comp / intersect.h: a
//   plane per pixel from barycentrics; PCSX2 SW GSRasterizer.cpp DrawTriangleSection + CDrawScanline:
//   per row, then vector steps; DobieStation gsthread.cpp render_half_triangle: one add per pixel), so
//   their values differ from this one and from each other in the last bits of a float. A model choice
//   (confidence low); evaluated in double from the exact integer edge functions (perspective.cpp,
//   built with -ffp-contract=off so the result does not depend on the compiler).
// - Division: S/Q and T/Q in float32, IEEE (PCSX2 SW CDrawScanline and, since PR #11248, the JIT's
//   SampleTexture `divps`; DobieStation render_half_triangle; Play! and PCSX2 HW fragment shaders;
//   parallel-gs sample_texture: 5 implementations). PCSX2 SW's reciprocal before PR #11248 (`rcpps`)
//   is CPU-dependent in its low bits and not modelled.
// - Range and conversion: the options stq_range and stq_convert (options.hpp).
// - Q = 0 at a vertex, Q of both signs, and non-finite S, T, Q are not modelled (the packet interpreter
//   names them). Q of one sign keeps its sign at every covered pixel (a convex combination), and
//   (−S)/(−Q) = S/Q in IEEE arithmetic, so parallel-gs's sign flip (triangle_setup.comp) and the
//   others' plain division agree there.
#pragma once

#include <array>
#include <cstdint>

#include "gs_arith/options.hpp"
#include "gs_arith/rasteriser.hpp"
#include "gs_arith/uv_plane.hpp"

namespace gs {

// One vertex's texture coordinates as written to the ST and RGBAQ registers.
struct stq {
  float S = 0.0f, T = 0.0f, Q = 1.0f;
};

// A triangle's S, T, Q planes: the vertices in window 12.4 coordinates, their doubled area
// (triangle_setup::area2, nonzero) and their S, T, Q.
struct stq_triangle {
  std::array<xy124, 3> v{};
  std::int64_t area2 = 0;
  std::array<stq, 3> a{};
};

// S, T, Q at window pixel (x, y), each the exact plane rounded to float32.
stq stq_at(const stq_triangle& t, int x, int y);

// One coordinate in 12.4 texels from S (or T) and Q: S/Q in float32, then stq_range, then times
// 2^size_log2 (exact), then stq_convert to sixteenths of a texel.
std::int32_t stq_texel(float s, float q, unsigned size_log2, const model_options& o);

// Both 12.4 texel coordinates at window pixel (x, y) of a texture 2^TW × 2^TH.
inline std::array<std::int32_t, 2> perspective_texel(const stq_triangle& t, int x, int y, unsigned TW, unsigned TH,
                                                     const model_options& o) {
  const stq p = stq_at(t, x, y);
  return {stq_texel(p.S, p.Q, TW, o), stq_texel(p.T, p.Q, TH, o)};
}

// The 12.4 texel coordinates a triangle drawn with FST = 0 samples, the one rule for the packet
// interpreter (gs_packets/draw.cpp) and the renderer (pipeline): per pixel (perspective_texel) when Q
// differs between the vertices; with one Q, S/Q and T/Q converted per vertex (stq_texel, clamped to the
// UV planes' ±2^20) and interpolated as UV are (make_uv_plane, uv_plane and uv_convert): PCSX2 SW
// ConvertVertexBuffer's `q_div` path and parallel-gs triangle_setup.comp with a fixed LOD (2 sources),
// a model choice.
struct stq_sampler {
  stq_triangle t;
  unsigned TW = 0, TH = 0;
  bool per_pixel = false;
  plane u, v;
  std::array<std::int32_t, 2> at(int x, int y, const model_options& o) const {
    return per_pixel ? perspective_texel(t, x, y, TW, TH, o) : std::array{u.at(x, y), v.at(x, y)};
  }
};
// A vertex's S/Q, T/Q as 12.4 texels (stq_texel), clamped to the UV planes' ±2^20: what the one-Q
// rule (and a sprite with FST = 0) interpolates.
std::array<std::int32_t, 2> stq_vertex_texel(const stq& v, unsigned TW, unsigned TH, const model_options& o);
// `t.area2` must be nonzero.
stq_sampler make_stq_sampler(const stq_triangle& t, unsigned TW, unsigned TH, const model_options& o);

}  // namespace gs

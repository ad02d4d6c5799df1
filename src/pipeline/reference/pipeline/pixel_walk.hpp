// pipeline/pixel_walk.hpp — the per-pixel inputs of a float evaluation on the GS render's geometry:
// the same visible triangle per pixel (from the GS render's step 1), the exact barycentric weights
// of the pixel centre in the 12.4 triangle, the same normal-map texel footprint (UV planes as the
// rasteriser sets them up, under the default uv_plane and uv_convert: the float reference takes no model option)
// and the tangent-space light interpolated with those weights. The float reference (reference.cpp)
// and the other seeds' schemes (scheme_method.hpp) both walk the frame through this one function, so
// they see the same pixels. Compiled with -ffp-contract=off.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "pipeline/prepare.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

struct pixel_sample {
  int x = 0, y = 0;
  std::size_t index = 0;          // y·width + x
  std::size_t triangle = 0;       // index into prepared_scene::triangles
  glm::dvec3 lambda{};            // barycentric weights of the pixel centre
  std::int32_t u16 = 0, v16 = 0;  // normal-map coordinates of the pixel, 12.4 texels (as the GS samples)
};

// Calls f for every pixel whose visible_triangle is ≥ 0, in raster order.
void for_each_covered_pixel(const prepared_scene& ps, const std::vector<std::int32_t>& visible_triangle,
                            const std::function<void(const pixel_sample&)>& f);
// The same over step 5's geometry: p.triangle indexes prepared_scene::plain, p.u16 / p.v16 are
// diffuse-texture coordinates (an empty plain_triangle: no pixel).
void for_each_plain_pixel(const prepared_scene& ps, const std::vector<std::int32_t>& plain_triangle,
                          const std::function<void(const pixel_sample&)>& f);

// Light `l` at the pixel: T = Σ λ_k T_k (not renormalised), fade = Σ λ_k fade_k.
struct pixel_light {
  glm::dvec3 T{};
  double fade = 0.0;
};
pixel_light interpolate_light(const prepared_scene& ps, std::size_t l, const pixel_sample& p);
// Light `l`'s spot intensity at the pixel (spot.hpp): spot_intensity at the projective coordinates
// Σλ_k S_k / Σλ_k Q_k, Σλ_k T_k / Σλ_k Q_k (the exact perspective-correct point; 0 when a vertex of the
// triangle is behind the light); 1 for a light that is not a spot light.
double interpolate_spot(const prepared_scene& ps, std::size_t l, const pixel_sample& p);

// A texel value filtered at (u16, v16): nearest, or the GS's 4-bit-weight bilinear blend of the four
// texels (gs::footprint) applied to the float values texel(u, v) returns (u, v unwrapped integers).
glm::dvec3 filtered(const std::function<glm::dvec3(std::int32_t, std::int32_t)>& texel, std::int32_t u16,
                    std::int32_t v16, bool bilinear);

// Texel (u, v) of a map with power-of-two sides, wrapped (REPEAT), as a row-major index.
constexpr std::size_t wrapped_texel(int width, int height, std::int32_t u, std::int32_t v) noexcept {
  return static_cast<std::size_t>(v & (height - 1)) * static_cast<std::size_t>(width) +
         static_cast<std::size_t>(u & (width - 1));
}

// The lit frame from per-light dot products d_l (1/128 units, NaN = not covered), composed as the
// GS methods' steps 2.6–4 do in float: diffuse · min(ambient + Σ colour_l · (max(d_l, 0)/128)^power, 255) / 128.
// Step 5's pixels (plain_triangle ≥ 0) in float, written into `colour`: the diffuse texel (filtered
// as the GS samples it) · Σ λ_k min(plain_light_k, 255) / 128, clamped to 255 — the VU1's per-vertex
// light interpolated without the GS's rounding of vertex colours, Gouraud steps or MODULATE's >> 7.
void compose_plain(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& plain_triangle,
                   bool bilinear, std::vector<std::uint32_t>& colour);

std::vector<std::uint32_t> compose_lit(const scene& s, const prepared_scene& ps,
                                       const std::vector<std::int32_t>& visible_triangle,
                                       const std::vector<std::vector<float>>& dot, bool bilinear, double power);

}  // namespace gsdot3::pipeline

// pipeline/prepare.hpp — the VU1's share (float, value level): transform, project to 12.4, cull,
// the per-vertex tangent-space tolight vectors T and fade_att for every light, and the
// non-normal-mapped geometry's per-vertex (Gouraud) light.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "pipeline/raster.hpp"
#include "pipeline/scene.hpp"
#include "pipeline/spot.hpp"

namespace gsdot3::pipeline {

// XYOFFSET: window pixel (0, 0) is primitive coordinate 2048.0, the middle of the GS's 4096² space;
// vertices outside the space (guard band) cannot be drawn.
inline constexpr std::int32_t xy_offset_pixels = 2048;

struct light_vertex {
  glm::vec3 T{};      // unit tolight (or half) vector in tangent space (t, b, n)
  float fade = 0.0f;  // fade_att = clamp(6·(n·l), 0, 1), section 3.6
};

struct prepared_triangle {
  std::array<std::uint32_t, 3> vertex{};              // mesh vertex indices
  triangle_setup setup;                               // window 12.4 coordinates
  plane z;                                            // 24-bit depth, larger is nearer
  std::array<std::int32_t, 3> z24{};                  // the vertices' depths the plane is made from (XYZ2.Z)
  std::array<std::array<std::int32_t, 2>, 3> uv16{};  // normal-map texel coordinates in 12.4
  std::uint16_t layer = 0;                            // the normal map's layer it samples (mesh::layer)
};

// Triangles [first, end) of a list.
struct triangle_range {
  std::uint32_t first = 0, end = 0;
};

struct prepared_scene {
  int width = 0, height = 0;
  // Front-facing, drawable, in mesh order by layer: layers[k] holds layer k's (one range, all of
  // them, for a one-layer map), as a PS2 renderer draws a pass material by material.
  std::vector<prepared_triangle> triangles;
  std::vector<triangle_range> layers;
  std::vector<std::vector<light_vertex>> lights;  // [light][mesh vertex]
  std::vector<std::vector<spot_vertex>> spots;    // [light][mesh vertex]: spot lights' (spot.hpp), else empty
  // Step 5 (scene::plain): its front-facing, drawable triangles (uv16 in diffuse-texture texels), and
  // per plain vertex the VU1's Gouraud light: ambient + Σ colour_l · max(n·l, 0) · spot_l (GS colour
  // units, 0x80 = 1.0; spot_l the spot light's spot_intensity at the vertex, 0 behind it), unclamped.
  std::vector<prepared_triangle> plain;
  std::vector<glm::vec3> plain_light;
  // Whether light l is a spot light (a scene prepared by hand may have no `spots` at all).
  bool spot(std::size_t l) const noexcept { return l < spots.size() && !spots[l].empty(); }
  // The layers, and layer k's triangles (one layer of every triangle when `layers` is empty: a scene
  // prepared by hand).
  std::size_t layer_count() const noexcept { return layers.empty() ? 1 : layers.size(); }
  triangle_range layer(std::size_t k) const noexcept {
    return layers.empty() ? triangle_range{0, static_cast<std::uint32_t>(triangles.size())} : layers[k];
  }
  int culled_back = 0, dropped_outside = 0;
};

// Throws std::invalid_argument when a triangle names a layer the normal map does not have.
// `yaw_degrees` turns the model about its vertical axis (180 = the back view of figure 7).
// `half_vectors`: T is the tangent-space half vector normalize(tolight + toeye) instead of the
// tolight vector (section 3.7, specular); fade_att still uses n·l.
prepared_scene prepare(const scene& s, float yaw_degrees = 0.0f, bool half_vectors = false);

}  // namespace gsdot3::pipeline

// pipeline/scene.hpp — what a render is made of: a mesh with per-vertex tangent frames, a
// palettised tangent-space normal map, a diffuse texture, lights, a camera, and optionally
// non-normal-mapped geometry beside the mesh.
// Everything here is float "VU1-side" data; the GS side starts in raster.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace gsdot3::pipeline {

struct vertex {
  glm::vec3 position{};
  glm::vec3 normal{};     // unit
  glm::vec3 tangent{};    // unit, orthogonal to normal (Gram-Schmidt)
  glm::vec3 bitangent{};  // unit, normal × tangent with the UV handedness
  glm::vec2 uv{};         // normal-map coordinates, 1.0 = one repeat of the map
};

struct mesh {
  std::vector<vertex> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
  // Per triangle, the layer of the scene's normal map its material samples (normal_map, "layers");
  // empty: layer 0 for every triangle.
  std::vector<std::uint16_t> layer;
};

// The layer triangle t of m samples.
inline std::uint16_t layer_of(const mesh& m, std::size_t t) { return m.layer.empty() ? 0 : m.layer[t]; }

// A palettised normal map: `index` is width·height palette indices, `palette` holds up to 2^bits
// unit tangent-space normals (z towards the viewer of the surface). bits 8: a PSMT8 texture with a
// 256-entry CLUT; 4: PSMT4 with 16 entries (section 3.8's "4/8 bit normal maps"; one index a byte here).
// `unquantised` holds the unit normals the palette was quantised from, one a texel. bits 24: those are
// read at 8 bits per component, section 3.6's "three 8 bit normal maps" (the four-pass method samples
// one map per axis pass, gs_inputs.hpp), and the float reference reads them (texel_normal); the methods
// that sample a texel's three components in one pass read the 8-bit map.
// Layers: a mesh whose materials have different maps (mesh::layer) has one layer per map, all
// width×height with the same bits, each with its own palette, as a PS2 renderer keeps one texture and
// CLUT per material: `index` and `unquantised` hold the layers' texels one layer after another,
// `palette` their palettes one after another, layer k's from palette_start[k] (empty: one layer).
struct normal_map {
  int width = 0, height = 0;
  std::vector<std::uint8_t> index;
  std::vector<glm::vec3> palette;
  std::vector<glm::vec3> unquantised;
  int bits = 8;
  std::vector<std::uint32_t> palette_start;
};

inline std::size_t layers(const normal_map& m) { return m.palette_start.empty() ? 1 : m.palette_start.size(); }
inline std::size_t layer_texels(const normal_map& m) {
  return static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height);
}
// The palette entry of texel i (row-major) of layer k: an index into `palette`.
inline std::size_t palette_entry(const normal_map& m, std::size_t k, std::size_t i) {
  return (m.palette_start.empty() ? 0 : m.palette_start[k]) + m.index[k * layer_texels(m) + i];
}
// The unit normal layer k holds at texel i: its palette entry, for a 24-bit map unquantised.
inline glm::vec3 texel_normal(const normal_map& m, std::size_t k, std::size_t i) {
  return m.bits == 24 ? m.unquantised[k * layer_texels(m) + i] : m.palette[palette_entry(m, k, i)];
}
// Layer k's palette.
inline std::vector<glm::vec3> layer_palette(const normal_map& m, std::size_t k) {
  const std::size_t from = m.palette_start.empty() ? 0 : m.palette_start.at(k);
  const std::size_t to = k + 1 < m.palette_start.size() ? m.palette_start[k + 1] : m.palette.size();
  return {m.palette.begin() + static_cast<std::ptrdiff_t>(from), m.palette.begin() + static_cast<std::ptrdiff_t>(to)};
}
// Layer k as a map of its own, and layers (same size and bits) as one map.
normal_map layer_map(const normal_map& m, std::size_t k);
normal_map stacked(const std::vector<normal_map>& layers);

// An RGB texture (A8B8G8R8 words, alpha 0x80) for the unlit diffuse pass.
struct texture32 {
  int width = 0, height = 0;
  std::vector<std::uint32_t> texels;
};

// Section 3 ("both methods work with directional, spot and point lights"): a point light at a world
// position, a directional light whose `position` is the world direction towards the light (any
// length; the same tolight vector at every vertex), or a spot light: a point light whose intensity is
// section 3.6's projective texture, a cone of half-angle `cone_degrees` about `direction`
// (spot.hpp's spot_intensity).
enum class light_kind { point, directional, spot };
struct scene_light {
  glm::vec3 position{};                  // point, spot: world position; directional: direction towards the light
  std::array<std::uint8_t, 3> colour{};  // GS colour units: 0x80 = 1.0
  light_kind kind = light_kind::point;
  bool gouraud = false;  // section 3.8: drawn with Gouraud shading, a co-located pair's cheap half (lod.hpp)
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // spot: the cone's axis (world, any length)
  float cone_degrees = 30.0f;              // spot: the cone's half-angle, 1..80
};

struct camera {
  glm::vec3 eye{0.0f, 0.0f, 3.0f};
  glm::vec3 target{0.0f, 0.0f, 0.0f};
  float fov_y_degrees = 40.0f;
};

struct scene {
  mesh model;
  // Section 3.1's step 5: "all non-normal mapped geometry, as one generally would, into the same
  // buffer" after step 4 — Gouraud-lit per vertex (every light, Lambert, no normal map), textured with
  // `diffuse` (its UVs, 1.0 = one repeat), depth-tested against the normal-mapped objects' Z and
  // writing its own. Empty: none (assets/floor.hpp makes a floor under the model).
  mesh plain;
  normal_map normals;
  texture32 diffuse;
  std::vector<scene_light> lights;
  std::array<std::uint8_t, 3> ambient{0x10, 0x10, 0x10};
  camera view;
  int width = 512, height = 448;
};

// Fills tangent and bitangent of every vertex from positions, normals and UVs (per-triangle UV
// derivatives accumulated per vertex, then Gram-Schmidt against the normal). Throws
// std::runtime_error naming the first triangle whose positions are degenerate (zero area).
void compute_tangents(mesh& m);

// Checks the mesh can be rendered: indices in range, finite values, unit-length normals after
// normalisation. Throws std::runtime_error with a one-line message.
void validate(const mesh& m);

}  // namespace gsdot3::pipeline

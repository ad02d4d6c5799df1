// pipeline/normal_map.hpp — making 8-bit palettised normal maps: from a height field, and from
// unit normals by vector quantisation (spherical k-means) to a 256-entry palette; 4-bit ones from those.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// Tangent-space unit normals of a width×height height field (wrapping at the borders), by central
// differences; `strength` scales the slopes (texels of height per texel of distance).
std::vector<glm::vec3> normals_from_height(const std::vector<float>& height, int width, int height_px, float strength);

// Quantises unit normals to at most `entries` palette entries by spherical k-means (assignment by
// largest dot product, centroids renormalised means), deterministic: seeds are chosen by farthest-point
// sampling from the first normal, iterations stop when no assignment changes (or after 30). The map
// keeps the normals as `unquantised`.
normal_map quantise(const std::vector<glm::vec3>& normals, int width, int height, int entries = 256);

// The map with `bits` per index, 4 (PSMT4, 16 entries) or 8 (PSMT8, 256), or read as 24 (its
// unquantised normals, scene.hpp): the same map when it has them; an 8-bit map to 4 bits by quantising
// its texels' normals (palette[index]) to 16 entries as above, the far level of detail made from the
// near one (section 3.8); a 4-bit map's indices are valid 8-bit ones; 24 from an 8-bit map only.
// A map of several layers: each layer so. Throws std::invalid_argument for any other bits.
normal_map with_index_bits(const normal_map& m, int bits);

}  // namespace gsdot3::pipeline

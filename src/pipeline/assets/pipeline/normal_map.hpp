// pipeline/normal_map.hpp — making 8-bit palettised normal maps: from a height field, and from
// unit normals by vector quantisation (spherical k-means) to a 256-entry palette.
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
// sampling from the first normal, iterations stop when no assignment changes (or after 30).
normal_map quantise(const std::vector<glm::vec3>& normals, int width, int height, int entries = 256);

}  // namespace gsdot3::pipeline

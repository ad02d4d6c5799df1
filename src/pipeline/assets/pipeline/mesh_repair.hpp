// pipeline/mesh_repair.hpp — from the meshes of a file (any importer) to the renderer's mesh:
// normals generated (generated_normals.hpp) or repaired, UVs projected
// where the file has none (uv_generation.hpp), tangents from the file or MikkTSpace,
// instances transformed into one space and merged. Counts go into the import report.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "pipeline/mesh_import.hpp"

namespace gsdot3::pipeline {

// One mesh of the file in its own coordinates; triangles only, indices in range, positions finite.
struct source_mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;     // empty: the file has none
  std::vector<glm::vec2> uvs;         // the renderer's convention (v runs down the image); empty: none
  std::vector<glm::vec3> tangents;    // empty: none; with them:
  std::vector<glm::vec3> bitangents;  // the file's bitangents (pointing up the image)
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::uint16_t layer = 0;  // the normal-map layer of its material (mesh::layer)
};

struct source_instance {
  std::size_t mesh = 0;
  glm::mat4 transform{1.0f};  // mesh coordinates to the model's
};

// Throws std::runtime_error (one line, without the file name) when no triangle is left or a UV is NaN/Inf.
mesh build_mesh(const std::vector<source_mesh>& meshes, const std::vector<source_instance>& instances,
                const import_options& options, import_report& report);

}  // namespace gsdot3::pipeline

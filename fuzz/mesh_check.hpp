// fuzz/mesh_check.hpp — the postconditions of an accepted mesh import (pipeline/mesh_import.hpp),
// shared by the harnesses that import meshes (parse_inputs from bytes, mesh_from_scene from scenes).
#pragma once

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "fuzz_check.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::fuzz {

// An accepted mesh has triangles with indices in range and unit, orthogonal tangent frames.
inline void check_mesh(const pipeline::mesh& m) {
  require(!m.triangles.empty(), [] { return std::string("import_mesh accepted a mesh without triangles"); });
  for (const auto& t : m.triangles) {
    for (auto i : t)
      require(i < m.vertices.size(), [] { return std::string("import_mesh accepted a triangle index out of range"); });
  }
  for (const pipeline::vertex& v : m.vertices) {
    const bool unit = std::fabs(glm::length(v.normal) - 1.0f) < 1e-3f &&
                      std::fabs(glm::length(v.tangent) - 1.0f) < 1e-3f &&
                      std::fabs(glm::dot(v.normal, v.tangent)) < 1e-3f;
    require(unit, [] { return std::string("import_mesh gave a vertex without a unit orthogonal normal and tangent"); });
  }
}

}  // namespace gsdot3::fuzz

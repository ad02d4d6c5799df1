// pipeline/mesh_info.hpp — what `gsdot3 mesh-info` prints about an imported mesh: the import report
// (what was read, repaired and generated) and figures measured on the mesh the renderer draws.
#pragma once

#include <cstddef>
#include <string>

#include <glm/vec3.hpp>

#include "pipeline/mesh_import.hpp"

namespace gsdot3::pipeline {

struct mesh_figures {
  std::size_t vertices = 0, triangles = 0;
  glm::vec3 lo{0.0f}, hi{0.0f};         // bounds of the positions (model space)
  double uv_area = 0.0;                 // Σ |UV area| over the triangles: how many repeats of the map cover the mesh
  std::size_t w_plus = 0, w_minus = 0;  // vertices by glTF handedness (TANGENT.w, mesh_export.hpp): −1 = mirrored UVs
};

mesh_figures measure(const mesh& m);

std::string mesh_info_json(const imported_mesh& im, const mesh_figures& f);  // one JSON object
std::string mesh_info_text(const imported_mesh& im, const mesh_figures& f);  // lines "name  value"

}  // namespace gsdot3::pipeline

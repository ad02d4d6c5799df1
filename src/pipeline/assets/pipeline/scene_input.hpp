// pipeline/scene_input.hpp — the scene `render`/`report` draw, from the user's files and options:
// the embedded scene, or a mesh (mesh_import.hpp) with its material's normal map, framed and lit
// (framing.hpp). Notices go to `notice` once each and into the input summary.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/input_report.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

struct scene_request {
  std::filesystem::path mesh, normal_map, height_map;  // empty: not given
  float bump = 0.05f;                                  // height-map slope scale
  import_options import;
  normal_map_settings normal_maps;
  std::optional<std::array<float, 2>> view;  // azimuth, elevation in degrees (meshes: default 0, 0)
  std::optional<glm::vec3> eye;              // --camera: looking at the origin
  std::vector<scene_light> lights;           // empty: the defaults
  bool floor = false;                        // step 5: a Gouraud-shaded floor under the model (floor.hpp)
  int width = 512, height = 448;
};

struct scene_input {
  scene s;
  input_summary summary;
  std::string description;  // one line for the report's scene entry
};

// Throws std::runtime_error "FILE: why" for unreadable or bad input.
scene_input make_scene(const scene_request& r, const std::function<void(const std::string&)>& notice);

}  // namespace gsdot3::pipeline

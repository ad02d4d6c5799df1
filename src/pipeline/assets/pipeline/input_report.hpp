// pipeline/input_report.hpp — what `render`/`report` read and what was done to it: report.json's
// top-level "input" object and a short "Input" section of report.html.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pipeline/mesh_import.hpp"
#include "pipeline/normal_map_image.hpp"

namespace gsdot3::pipeline {

struct input_summary {
  std::optional<import_report> mesh;                        // none: the embedded head
  std::string normal_map_source = "procedural (embedded)";  // or "--normal-map FILE", "material of the mesh: NAME", …
  std::optional<loaded_normal_map> normal_map;              // what was decoded (map itself not written)
  std::string normal_map_y = "up";
  // A mesh whose materials name normal maps: one line per layer (scene.hpp), its map and its materials.
  std::vector<std::string> layers;
  std::string camera = "embedded scene's";  // or "framed (azimuth A, elevation E)", "--camera X,Y,Z"
  std::string lights = "embedded scene's";  // or "default, turned with the view", "--light"
  std::vector<std::string> notices;         // every notice, in order (the mesh's included)
};

std::string input_json(const input_summary& s);  // a JSON object, one line
std::string mesh_json(const import_report& r);   // its "mesh" object (also gsdot3 mesh-info's)
std::string input_html(const input_summary& s);  // <h2>Input</h2> and a small table

}  // namespace gsdot3::pipeline

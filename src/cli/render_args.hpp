// cli/render_args.hpp — the options of gsdot3 render and report (and of the commands that draw the
// same frame: scene_options.hpp), their parsing into the scene, the render options and the methods.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cost_args.hpp"
#include "import_options.hpp"
#include "model_args.hpp"
#include "scene_options.hpp"

namespace gsdot3::cli {

struct render_args {
  std::string out = "gsdot3-out", method = "all", mesh, normal_map, size = "512x448", filter = "nearest",
              path = "cached";
  std::string camera, height_map;
  std::string normal_map_y = "up", view, export_mesh;
  import_args import;
  float bump = 0.05f;
  std::vector<std::string> lights;
  model_args model;
  int s = 122, threads = 2;
  std::optional<double> specular;  // the ILP power; unset: diffuse
  std::optional<double> lod_share;
  std::string lod_distance;  // NEAR,FAR: the share from the camera's distance (lod.hpp's lod_share_at)
  int normal_map_bits = 8;
  bool memory_path = false, scalar = false;
  bool floor = false;  // step 5's geometry
  bool spot_after_first_pass = false;
  std::string dpb_clear = "explicit";
  int draw_buffers = 2;
  bool cost = false;  // render / report only: --cost and the cost model's options
  cost_args cost_model;
};

// Registers render's scene, model and method options (everything but --out, --export-mesh, --cost).
void add_options(CLI::App* cmd, render_args& a);
// The scene, the render options and the methods of render's options; throws usage_error for bad
// options and for a frame `use` does not draw (pipeline/frame_limits.hpp).
scene_setup setup(const render_args& a, pipeline::frame_use use);
// One progress line on stderr: "gsdot3: M".
void progress(const std::string& m);

}  // namespace gsdot3::cli

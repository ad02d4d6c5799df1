// cli/scene_options.hpp — render's scene, model and method options (--method, --mesh, --light,
// --size, --s, --filter, --model-option, ... : everything but --out) for other commands that draw
// the same frame (gsdot3 dump).
#pragma once

#include <functional>
#include <vector>

#include <CLI/CLI.hpp>

#include "pipeline/frame_limits.hpp"
#include "pipeline/render.hpp"
#include "pipeline/scene_input.hpp"
#include "pipeline/scheme_method.hpp"

namespace gsdot3::cli {

struct scene_setup {
  pipeline::scene_input in;
  pipeline::render_options options;
  std::vector<pipeline::method> methods;
  std::vector<const pipeline::scheme_method*> schemes;
};

// Registers the options on cmd; the function parses them and builds the scene, and throws usage_error
// for bad options and for a frame `use` does not draw (pipeline/frame_limits.hpp).
std::function<scene_setup()> add_scene_options(CLI::App* cmd, pipeline::frame_use use);

}  // namespace gsdot3::cli

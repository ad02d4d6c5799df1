// cli/cost_args.hpp — the GS cost model's options a command takes (gs_cost/constants.hpp: what no
// source states is an option): one set of flags for `gsdot3 cost` and `gsdot3 report --cost`.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "gs_cost/constants.hpp"

namespace gsdot3::cli {

struct cost_args {
  std::string walk = "blocks", texture_unit = "page";
  gs::cost::cost_options o{};

  void add_to(CLI::App* cmd);
  // The options with --walk and --texture-miss-unit applied; usage_error on a bad value.
  gs::cost::cost_options resolve() const;
};

}  // namespace gsdot3::cli

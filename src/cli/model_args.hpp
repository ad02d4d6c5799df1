// cli/model_args.hpp — the GS model options a command takes: --profile NAME (an emulator's option
// set, gs_arith/profiles.hpp) and a repeatable NAME=VALUE flag (--option or --model-option, the
// command's existing name) applied over it. One parser for every command that runs the model.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "gs_arith/options.hpp"

namespace gsdot3::cli {

// "NAME=VALUE" split at the first '='; usage_error naming `what` when there is none or NAME is empty.
std::pair<std::string, std::string> split_assignment(const std::string& what, const std::string& text);

struct model_args {
  explicit model_args(std::string name_value_flag = "--model-option") : flag(std::move(name_value_flag)) {}
  std::string flag;  // the NAME=VALUE flag's name
  std::string profile;
  std::vector<std::string> options;

  // Registers --profile and `flag` on cmd; `what` says what the options apply to (e.g. "for --png").
  void add_to(CLI::App* cmd, const std::string& what = "");
  // The default options, the profile's over them, then each NAME=VALUE in order; usage_error on a bad one.
  gs::model_options resolve() const;
};

}  // namespace gsdot3::cli

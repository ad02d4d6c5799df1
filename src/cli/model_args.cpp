#include "model_args.hpp"

#include "commands.hpp"
#include "gs_arith/profiles.hpp"

namespace gsdot3::cli {

std::pair<std::string, std::string> split_assignment(const std::string& what, const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw usage_error(what + ": expected NAME=VALUE, got '" + text + "'");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

void model_args::add_to(CLI::App* cmd, const std::string& what) {
  const std::string tail = what.empty() ? "" : " " + what;
  cmd->add_option(flag, options, "GS model option NAME=VALUE" + tail + " (repeatable; `gsdot3 alu --help` lists them)");
  cmd->add_option("--profile", profile,
                  "GS model options of an emulator" + tail + " (" + gs::profile_names() + ", docs/evidence.md); " +
                      flag + " overrides it");
}

gs::model_options model_args::resolve() const {
  gs::model_options o;
  if (!profile.empty())
    if (auto err = gs::apply_profile(o, profile)) throw usage_error("--profile: " + *err);
  for (const std::string& item : options) {
    const auto [name, value] = split_assignment(flag, item);
    if (auto err = gs::set_option(o, name, value)) throw usage_error(flag + ": " + *err);
  }
  return o;
}

}  // namespace gsdot3::cli

// gs_arith/profiles.hpp — named option sets: the model set up the way one emulator computes.
//
// Built from the behaviour matrix (docs/evidence.md; tests/gs_arith/evidence_test.cpp checks that
// every row names these values). A profile sets every model option, so
// `gsdot3 vectors gen --profile dobiestation` writes vectors that emulator should pass today (except
// for the behaviours the matrix lists as emulator defects, which no option reproduces), and
// `gsdot3 prove --profile NAME` shows which of the paper's claims it would change.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gs_arith/options.hpp"

namespace gs {

struct profile {
  std::string_view name;                                              // --profile NAME
  std::string_view source;                                            // the emulator and code it follows
  std::vector<std::pair<std::string_view, std::string_view>> values;  // option name -> value, every option
};
const std::vector<profile>& profiles();

// "pcsx2-sw, dobiestation, play".
std::string profile_names();

// Sets every option of profile NAME in `opts`; returns an error message for an unknown name.
std::optional<std::string> apply_profile(model_options& opts, std::string_view name);

}  // namespace gs

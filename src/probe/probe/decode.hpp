// probe/decode.hpp — which option values a screenshot of the probe frame shows.
//
// For every option of gs::option_catalogue() with patches, the model's frame is computed under each
// of its values (the other options at their defaults; tests/probe checks that no patch depends on
// another option) and compared with the screenshot on the option's patches (the inner 6×6 pixels of
// each cell, RGB only). A value matches when every sampled pixel of every patch of the option agrees.
// Checks (patches of behaviours the model fixes) are compared with the default frame only.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gs_arith/options.hpp"

namespace gsdot3::probe {

// frame_width × frame_height pixels as 0xRRGGBB, rows top first.
using rgb_frame = std::vector<std::uint32_t>;

struct verdict {
  std::string name;  // an option name, or a check's name
  bool is_check = false;
  std::string not_probed;            // the reason, for an option no patch tells apart
  std::vector<std::string> matches;  // values (a check: "model") that agree on every patch
  std::vector<std::string> details;  // when nothing matches: one line per disagreeing patch
};

std::vector<verdict> decode(const rgb_frame& shot);

// "NAME: VALUE" / "NAME: none matches" + details / "NAME: not probed (...)", one verdict per line.
std::string format_verdicts(const std::vector<verdict>& v);

// The model's frame under options o (by default every option's default) as RGB: what a screenshot of
// a console that behaves like those options shows.
rgb_frame model_rgb_frame(const gs::model_options& o = {});

}  // namespace gsdot3::probe

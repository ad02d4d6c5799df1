// pipeline/console_time.hpp — what a method's frame costs on the console: the frame's GIF stream
// (frame_packets.hpp, the stream `gsdot3 dump` writes) priced by the GS cost model (src/gs_cost,
// docs/cost.md) as it replays, so the report's PS2 time and `gsdot3 cost` on the dump are one figure.
#pragma once

#include <optional>
#include <string>

#include "gs_cost/model.hpp"
#include "pipeline/method.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

struct console_time {
  std::optional<gs::cost::frame_cost> frame;  // empty when the frame cannot be written as a stream
  std::string not_priced;                     // why (frame_packets.hpp's "Not written"), else empty
};

console_time price_frame(const scene& s, const prepared_scene& ps, method m, const render_options& o,
                         const gs::cost::cost_options& c = {});

}  // namespace gsdot3::pipeline

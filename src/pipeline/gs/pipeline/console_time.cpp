// pipeline/console_time.cpp — see console_time.hpp.
#include "pipeline/console_time.hpp"

#include <stdexcept>

#include "pipeline/frame_packets.hpp"

namespace gsdot3::pipeline {

console_time price_frame(const scene& s, const prepared_scene& ps, method m, const render_options& o,
                         const gs::cost::cost_options& c) {
  frame_packets fp;
  try {
    fp = build_frame_packets(s, ps, m, o);
  } catch (const std::invalid_argument& e) { return {std::nullopt, e.what()}; } catch (const texture_does_not_fit& e) {
    return {std::nullopt, e.what()};
  }
  const auto frames = gs::cost::price_dump(frame_dump(fp), c);
  if (frames.size() != 1)
    throw std::logic_error("price_frame: the stream of one frame priced as " + std::to_string(frames.size()) +
                           " frames");
  return {frames.front(), {}};
}

}  // namespace gsdot3::pipeline

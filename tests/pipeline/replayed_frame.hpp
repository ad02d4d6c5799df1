// A frame's GS dump as `gsdot3 dump` writes it, written to bytes, read back and replayed through the
// packet interpreter (gs_packets): the output buffer (DISPFB1's) with alpha 0xFF, as frame::colour
// has it, and what the interpreter did not model. The tests compare it with the renderer's frame.
#pragma once

#include <cstdint>
#include <vector>

#include "gs_packets/dump.hpp"
#include "gs_packets/interpreter.hpp"
#include "pipeline/frame_packets.hpp"

namespace gsdot3::pipeline {

struct replayed_frame {
  std::vector<std::uint32_t> colour;
  std::vector<gs::packets::unmodelled> unmodelled;
};

inline replayed_frame replay_frame(const frame_packets& fp, const gs::model_options& model) {
  const gs::dump::gs_dump d = gs::dump::read_dump(gs::dump::write_dump(frame_dump(fp)));
  gs::mem::local_memory mem;
  gs::packets::interpreter gs(mem, {model, false});
  gs.replay(d);
  const gs::mem::buffer out = fp.buffers.colour(fp.buffers.output());
  replayed_frame r{{}, gs.unmodelled_features()};
  for (int y = 0; y < fp.height; ++y)
    for (int x = 0; x < fp.width; ++x)
      r.colour.push_back(mem.read_pixel(out, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)) |
                         0xFF000000u);
  return r;
}

}  // namespace gsdot3::pipeline

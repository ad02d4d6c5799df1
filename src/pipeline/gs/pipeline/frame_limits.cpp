#include "pipeline/frame_limits.hpp"

#include <algorithm>
#include <stdexcept>

#include "pipeline/gs_inputs.hpp"

namespace gsdot3::pipeline {

std::optional<std::string> broken_limit(const scene& s, method m, const render_options& o, frame_use use) {
  const std::string size = std::to_string(s.width) + "x" + std::to_string(s.height);
  const bool z_trick = o.dpb_clear != dpb_clear_mode::explicit_clear;
  if (use == frame_use::packets && (s.width > 1023 || s.height > 1023))
    return "frame packets: " + size + ": a sprite's UV (10.4) reaches 1023 texels, so frames are at most 1023x1023";
  const bool in_memory = use == frame_use::packets || o.memory_path || z_trick;
  if (in_memory && !buffer_layout_for(s.width, s.height).fits())
    return "memory path: four " + size +
           " PSMCT32 buffers (DPB, LAB, output, Z) do not fit in the GS's 4 MiB (512 pages); the memory path, "
           "--dpb-clear z-trick* and gsdot3 dump need them";
  const auto lights_where = [&](auto&& p) { return std::any_of(s.lights.begin(), s.lights.end(), p); };
  const bool lod_pairs = lights_where([](const scene_light& l) { return l.gouraud; });
  if (o.buffers == draw_buffers::one) {
    if (s.lights.size() > max_free_alpha_lights)
      return "--draw-buffers 1: " + std::to_string(s.lights.size()) +
             " lights, but the one-buffer variant keeps at most " + std::to_string(max_free_alpha_lights) +
             " dot layers in free alphas (section 3.1)" +
             (lod_pairs ? "; the level of detail (--lod-fade, --lod-distance) makes each light a pair" : "");
    if (z_trick)
      return "--draw-buffers 1 needs --dpb-clear explicit (the z-trick clears use the Z buffer's top byte, which this "
             "variant keeps a free alpha in)";
  }
  if (lod_pairs && lights_where([](const scene_light& l) { return l.kind == light_kind::spot; }))
    return "--light spot:... and --lod-fade / --lod-distance: spot lights are not split into section 3.8's LOD pairs";
  if (o.spot_after_first_pass && m != method::four_pass)
    return "--spot-after-first-pass: four-pass's placement (section 3.6), not " + std::string(name(m)) +
           "'s; use --method four-pass";
  return std::nullopt;
}

void check(const scene& s, method m, const render_options& o, frame_use use) {
  if (const std::optional<std::string> why = broken_limit(s, m, o, use)) throw std::invalid_argument(*why);
}

}  // namespace gsdot3::pipeline

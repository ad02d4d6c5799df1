// probe/frame.hpp — the frame the model predicts for the probe: every draw of probe_design() through
// gs_memory (texture upload, texel fetches, frame reads and writes) and gs::pixel_pipeline, under the
// given model options. This is the readable reference the decoder compares a screenshot with.
//
// Rasterisation, as the design needs it (design.hpp keeps patches away from its edge cases): a sprite
// covers the pixels x0 <= x < x1, y0 <= y < y1 (its vertex colour is the second vertex's); a triangle
// the pixels whose integer centre lies inside or on its edges; both clipped to SCISSOR_1. Every vertex
// of a textured primitive carries the same UV, sampled with gs::sample (NEAREST, or the `bilinear`
// option when TEX1 is LINEAR) through gs_memory's texture_page_buffer under the `texture_buffer`
// option; the buffer starts empty at a TEXFLUSH or a change of drawing state.
#pragma once

#include <cstdint>
#include <vector>

#include "gs_arith/options.hpp"

namespace gsdot3::probe {

// The displayed frame, frame_width × frame_height PSMCT32 words (A8B8G8R8), rows top first.
std::vector<std::uint32_t> model_frame(const gs::model_options& o);

// The 0xRRGGBB a screenshot shows for a frame word (the display's alpha is not compared).
constexpr std::uint32_t rgb_of(std::uint32_t word) noexcept {
  return (word & 0xFFu) << 16 | (word & 0xFF00u) | (word >> 16 & 0xFFu);
}

}  // namespace gsdot3::probe

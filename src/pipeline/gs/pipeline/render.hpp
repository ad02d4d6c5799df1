// pipeline/render.hpp — whole frames through the modeled GS: the paper's steps 1–5 (section 3.1)
// with the two-pass (3.5), four-pass (3.6) or Breugelmans 2002 (section 2) signed multiplications.
#pragma once

#include "pipeline/method.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// Throws std::invalid_argument for a frame the options ask for that the model does not draw:
// frame_limits.hpp's check, and on the memory path step 5 with streamed textures (gs_inputs.hpp).
frame render(const scene& s, const prepared_scene& ps, method m, const render_options& o);

}  // namespace gsdot3::pipeline

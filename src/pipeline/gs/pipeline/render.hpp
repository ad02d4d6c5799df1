// pipeline/render.hpp — whole frames through the modeled GS: the paper's steps 1–4 (section 3.1)
// with the two-pass (3.5), four-pass (3.6) or Breugelmans 2002 (section 2) signed multiplications.
#pragma once

#include "pipeline/method.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

frame render(const scene& s, const prepared_scene& ps, method m, const render_options& o);

}  // namespace gsdot3::pipeline

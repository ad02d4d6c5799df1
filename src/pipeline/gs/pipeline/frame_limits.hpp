// pipeline/frame_limits.hpp — every limit on a frame the GS methods draw, in one function: the
// renderer (both paths) and the GIF packet stream call check() before they draw, and the CLI asks
// broken_limit() once and reports it as a usage error. Limits found only while the textures are
// placed (no room to stream them, step 5 with streamed textures) stay with the placement
// (gs_inputs.hpp's texture_does_not_fit and plain_needs_resident_texture).
#pragma once

#include <optional>
#include <string>

#include "pipeline/method.hpp"
#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

// Who draws the frame: the renderer (the value path, or the modelled local memory when
// render_options::memory_path or a z-trick clear asks for it) or the GIF packet stream of `gsdot3
// dump` (always in local memory).
enum class frame_use { render, packets };

// The first limit the frame of method m breaks under o, as one line naming the option, or nothing.
std::optional<std::string> broken_limit(const scene& s, method m, const render_options& o, frame_use use);

// Throws std::invalid_argument with broken_limit's line.
void check(const scene& s, method m, const render_options& o, frame_use use);

}  // namespace gsdot3::pipeline

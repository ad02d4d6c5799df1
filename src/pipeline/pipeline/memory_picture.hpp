// pipeline/memory_picture.hpp — a picture of how one storage format's page lies over another's in GS
// local memory (gs_memory/overlay.hpp), e.g. a PSMCT32 page read as PSMT8: section 3.3's swizzle.
#pragma once

#include <string_view>

#include "gs_memory/format.hpp"
#include "pipeline/files.hpp"

namespace gsdot3::pipeline {

// One page of `view` (its page size × scale); colour "channel": the part of the base pixel each
// texel reads (the base unit's quarters R, G, B, A as red, green, blue, grey; shaded by the base
// pixel's x within its 8-pixel group); "pixel": the base pixel's position (red = x, green = y).
// Block edges of the view format are drawn from scale 3 up.
image page_overlay_image(gs::mem::psm base, gs::mem::psm view, std::string_view colour, int scale);

}  // namespace gsdot3::pipeline

// pipeline/memory_picture.hpp — a picture of how one storage format's page lies over another's in GS
// local memory (gs_memory/overlay.hpp), e.g. a PSMCT32 page read as PSMT8: section 3.3's swizzle.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "gs_memory/format.hpp"
#include "pipeline/files.hpp"
#include "pipeline/method.hpp"

namespace gsdot3::pipeline {

// One page of `view` (its page size × scale); colour "channel": the part of the base pixel each
// texel reads (the base unit's quarters R, G, B, A as red, green, blue, grey; shaded by the base
// pixel's x within its 8-pixel group); "pixel": the base pixel's position (red = x, green = y).
// Block edges of the view format are drawn from scale 3 up.
image page_overlay_image(gs::mem::psm base, gs::mem::psm view, std::string_view colour, int scale);

// A rendered DPB in GS local memory: a traced memory-path frame's DPB (logical pixels, the words
// the post filter of light 0 reads: the pass before "2.4 R += G") written back where the renderer
// keeps it (FBP 0, FBW = ceil(w / 64), PSMCT32, or PSMZ32 when the DPB was drawn in the Z layout).
// `display`: the buffer as the GS's display circuit shows a PSMCT32 frame (w × h, RGB, alpha not
// shown); `as_psmt8`: the same memory as the PSMT8 texture of the post filter (TBP0 = 0, TBW = 2·FBW,
// 2w × 2h texels, grey = the texel byte) — section 3.3's swizzle on real data.
struct dpb_pictures {
  image display, as_psmt8;
};
dpb_pictures post_filter_dpb_pictures(const std::vector<pass_record>& trace, int w, int h, bool z_layout);

}  // namespace gsdot3::pipeline

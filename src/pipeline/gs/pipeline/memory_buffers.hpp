// pipeline/memory_buffers.hpp — the memory path's frame buffers in the modelled local memory (internal to
// render.cpp): gs_inputs.hpp's buffer layout (the DPB, in step 3 also the diffuse layer, the LAB, the output as
// PSMCT32, the Z buffer as PSMZ24, FBW = ceil(width / 64)) as memory_views with their address tables.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "gs_memory/fast_address.hpp"
#include "gs_memory/local_memory.hpp"
#include "pipeline/channel_pass.hpp"
#include "pipeline/frame_program.hpp"
#include "pipeline/gs_inputs.hpp"
#include "pipeline/table_cache.hpp"

namespace gsdot3::pipeline::detail {

// The views, and the tables they point into (kept here: table_cache.hpp may drop its own).
struct memory_buffers {
  frame_buffers<memory_view> fb;
  std::shared_ptr<const gs::mem::texel_addresses> page_as_t8;
  std::vector<std::shared_ptr<const gs::mem::row_column_address>> addresses;

  memory_buffers(gs::mem::local_memory& memory, const buffer_layout& layout, dpb_clear_mode clear, int height) {
    const std::uint32_t fbw = layout.fbw;
    fb.memory = &memory;
    fb.layout = layout;
    fb.clear = clear;
    fb.dpb = memory_view{memory.words(), 32 * layout.dpb(), fbw, false};
    fb.lab = memory_view{memory.words(), 32 * layout.lab(), fbw, false};
    fb.out = memory_view{memory.words(), 32 * layout.output(), fbw, false};
    fb.diff = fb.dpb;
    fb.zb.memory = memory_view{memory.words(), 32 * layout.z(), fbw, true};
    fb.zb.in_memory = true;
    fb.dpb.z = in_z_layout(buffer_role::dpb, clear);
    fb.lab.z = in_z_layout(buffer_role::lab, clear);
    // The inner loops' addresses tabulated over whole pages (gs_memory/fast_address.hpp).
    page_as_t8 = cached_table<gs::mem::texel_addresses>(gs::mem::psm::PSMT8, 2 * fbw, std::uint32_t{128},
                                                        std::uint32_t{64});  // channel_pass's TBW
    fb.page_as_t8 = page_as_t8.get();
    fb.alpha_plane[1] = memory_view{memory.words(), 32 * layout.z(), fbw, false};
    const auto rows = 32 * static_cast<std::uint32_t>((height + 31) / 32);
    for (memory_view* v : {&fb.dpb, &fb.lab, &fb.diff, &fb.out, &fb.zb.memory, &fb.alpha_plane[1]})
      v->address =
          addresses.emplace_back(cached_table<gs::mem::row_column_address>(v->layout(), v->bp, v->bw, 64 * fbw, rows))
              .get();
    fb.alpha_plane[0] = fb.dpb, fb.alpha_plane[2] = fb.out;  // with their address tables
  }
};

}  // namespace gsdot3::pipeline::detail
